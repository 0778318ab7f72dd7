package dolphin.sim

import com.MAVLink.Messages.MAVLinkMessage
import com.MAVLink.minimal.msg_heartbeat
import dolphin.core.Position

import java.lang.reflect.Field
import java.nio.file.Path

/**
 * A recorded session between our ground station and one real ArduPilot SITL vehicle (system 1),
 * on the vehicle's clock: each frame the ground station sent is placed at the vehicle's boot time
 * (time_boot_ms) last seen before it, or, before the vehicle sent any, at the first it sends. The
 * vehicle's heartbeat comes once a second at a phase of its own (SITL's differs from run to run), taken
 * from the boot time before its first heartbeat that follows one.
 */
class Recording {

    static final int VEHICLE = 1

    static class Sent {
        final long bootNanos
        final MAVLinkMessage message

        Sent(long bootNanos, MAVLinkMessage message) {
            this.bootNanos = bootNanos
            this.message = message
        }
    }

    /** What the vehicle sent, in order. */
    final List<MAVLinkMessage> vehicle = []
    /** The same, each at the vehicle's boot time last seen at or before it (its own, if it carries one); 0 before the first. */
    final List<Sent> vehicleTimed = []
    /** What the ground station sent, in order and on the vehicle's clock: its heartbeats too, which a PX4 vehicle waits for to send its texts. */
    final List<Sent> groundStation = []
    /** The vehicle's boot time at its last frame. */
    long endNanos
    /** When in each second of the vehicle's clock its heartbeat comes, in nanoseconds (0 to 1 s). */
    long heartbeatPhaseNanos

    private static final Map<Class, Field> BOOT_TIME = [:]

    static Recording read(Path tlog) {
        def recording = new Recording()
        List<MAVLinkMessage> untimed = []
        Long boot = null
        Long phase = null
        TlogFile.read(tlog).each { record ->
            MAVLinkMessage m = record.frame.message()
            if (m == null) {
                return
            }
            if (record.frame.sysid() == VEHICLE) {
                if (m instanceof msg_heartbeat && boot != null && phase == null) {
                    phase = Math.floorMod(boot, 1000L) * 1_000_000L
                }
                recording.vehicle << m
                Long t = bootMillis(m)
                if (t != null) {
                    boot = t
                    untimed.each { recording.groundStation << new Sent(t * 1_000_000L, it) }
                    untimed.clear()
                }
                recording.vehicleTimed << new Sent((boot ?: 0L) * 1_000_000L, m)
            } else if (boot == null) {
                untimed << m
            } else {
                recording.groundStation << new Sent(boot * 1_000_000L, m)
            }
        }
        recording.endNanos = (boot ?: 0L) * 1_000_000L
        recording.heartbeatPhaseNanos = phase ?: 0L
        recording
    }

    private static Long bootMillis(MAVLinkMessage m) {
        Field f = BOOT_TIME.computeIfAbsent(m.class) { c -> c.fields.find { it.name == 'time_boot_ms' } }
        f == null ? null : (f.getLong(m))
    }

    /**
     * What a simulated vehicle of {@code kind}, booted when the recorded one was, sends when the
     * ground station's frames reach it at the recorded times, until the recording ends. The simulator
     * sends its heartbeat on the second of its boot, so it is booted up to a second earlier, at the
     * recorded heartbeat's phase: a heartbeat between two of the ground station's commands shows the
     * vehicle's state only if SITL's did. Its home is SITL's {@code --home}: SimDriver.HOME, where the copter, plane and rover were recorded, unless given.
     */
    List<MAVLinkMessage> replay(VehicleKind kind, SimOptions options, Position home = SimDriver.HOME) {
        replayed(kind, options, home).sent*.message
    }

    /**
     * The driver of that replay, its clock at the recording's end: its clock is the recorded
     * vehicle's time since boot, so what it sent is timed as {@link #vehicleTimed} is.
     */
    SimDriver replayed(VehicleKind kind, SimOptions options, Position home = SimDriver.HOME) {
        def driver = new SimDriver(kind, options, home, heartbeatPhaseNanos - 1_000_000_000L)
        groundStation.each { sent ->
            driver.runTo(sent.bootNanos)
            driver.handle(sent.message, sent.message.sysid, sent.message.compid)
        }
        driver.runTo(endNanos)
        driver
    }
}
