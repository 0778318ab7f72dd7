package dolphin.sim

import com.MAVLink.Messages.MAVLinkMessage
import com.MAVLink.common.msg_command_ack
import com.MAVLink.common.msg_command_long
import com.MAVLink.common.msg_mission_ack
import com.MAVLink.common.msg_mission_count
import com.MAVLink.common.msg_mission_request
import com.MAVLink.common.msg_statustext
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_MODE_FLAG
import dolphin.core.Position
import dolphin.mission.model.MissionItem
import dolphin.mission.model.MissionType

/**
 * Drives one {@link SimVehicle} directly, without sockets or real time: its clock is the nanoseconds
 * given to tick and handle, advanced in the fleet's 50 ms ticks, and every frame it sends is kept
 * with the clock time it was sent at. What "the ground station" sends is handled at once.
 */
class SimDriver {

    static final long TICK = 50_000_000L
    static final Position HOME = Position.fromDegrees(40.444233, -7.375234, 820)

    static class Sent {
        final long at
        final MAVLinkMessage message

        Sent(long at, MAVLinkMessage message) {
            this.at = at
            this.message = message
        }
    }

    final SimVehicle vehicle
    final List<Sent> sent = []
    long now

    /** Vehicle {@code sysid} booted at clock time {@code boot} (nanoseconds), with what {@code equipment} gives it. */
    SimDriver(VehicleKind kind, SimOptions options = SimOptions.DEFAULT, Position home = HOME, long boot = 0,
              SimEquipment equipment = SimEquipment.NONE, int sysid = 1) {
        now = boot
        vehicle = new SimVehicle(sysid, kind, home, options, boot, equipment)
        vehicle.connect { MAVLinkMessage m -> sent << new Sent(now, m) }
    }

    double seconds() {
        now / 1e9
    }

    /** Handles {@code m} as sent by (sysid, compid), at the current time. */
    void handle(MAVLinkMessage m, int sysid = 255, int compid = 190) {
        m.sysid = sysid
        m.compid = compid
        vehicle.handle(m, now)
    }

    void tick() {
        now += TICK
        vehicle.tick(now)
    }

    /** Ticks for {@code seconds} of clock time. */
    void run(double seconds) {
        long end = now + (long) (seconds * 1e9)
        while (now < end) {
            tick()
        }
    }

    /** Ticks until clock time {@code nanos}. */
    void runTo(long nanos) {
        while (now + TICK <= nanos) {
            tick()
        }
    }

    /** Ticks until the condition holds; fails after {@code seconds} of clock time. */
    void runUntil(double seconds, String what, Closure<Boolean> condition) {
        long end = now + (long) (seconds * 1e9)
        while (!condition()) {
            if (now >= end) {
                throw new AssertionError("no ${what} within ${seconds} s of clock time; the vehicle sent " +
                        sent.collect { it.message.class.simpleName - 'msg_' }.countBy { it })
            }
            tick()
        }
    }

    int mark() {
        sent.size()
    }

    public <T> List<T> since(int from, Class<T> type) {
        sent.drop(from)*.message.findAll { type.isInstance(it) } as List<T>
    }

    List<String> texts(int from = 0) {
        since(from, msg_statustext)*.text
    }

    /** The index of the first frame sent after {@code from} that matches, or -1. */
    int indexOf(int from, Closure<Boolean> match) {
        for (int i = from; i < sent.size(); i++) {
            if (match(sent[i].message)) {
                return i
            }
        }
        -1
    }

    def command(int command, List<Number> params = []) {
        int from = mark()
        def p = (params + [0] * 7).take(7)
        handle(new msg_command_long(target_system: vehicle.sysid(), target_component: 1, command: command, param1: p[0], param2: p[1],
                param3: p[2], param4: p[3], param5: p[4], param6: p[5], param7: p[6]))
        since(from, msg_command_ack).find { it.command == command }
    }

    def setMode(int mode) {
        command(MAV_CMD.MAV_CMD_DO_SET_MODE, [MAV_MODE_FLAG.MAV_MODE_FLAG_CUSTOM_MODE_ENABLED, mode])
    }

    def arm() {
        command(MAV_CMD.MAV_CMD_COMPONENT_ARM_DISARM, [1])
    }

    /** Uploads items (seq 0 first), answering each MISSION_REQUEST at once; the final MISSION_ACK's type. */
    int upload(List<MissionItem> items, MissionType type = MissionType.MISSION) {
        int from = mark()
        handle(new msg_mission_count(target_system: 1, target_component: 1, count: items.size(), mission_type: (short) type.wire()))
        for (int seen = from; ; seen++) {
            assert seen < sent.size(): "the upload stalled: ${sent.drop(from)*.message}"
            def m = sent[seen].message
            if (m instanceof msg_mission_request) {
                handle(items[m.seq].toMessage(1, 1, type))
            } else if (m instanceof msg_mission_ack) {
                return m.type
            }
        }
    }
}
