package dolphin.sim

import com.MAVLink.Messages.MAVLinkMessage
import com.MAVLink.common.msg_command_ack
import com.MAVLink.common.msg_extended_sys_state
import com.MAVLink.common.msg_file_transfer_protocol
import com.MAVLink.common.msg_mission_ack
import com.MAVLink.common.msg_mission_current
import com.MAVLink.common.msg_mission_item_reached
import com.MAVLink.common.msg_statustext
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_MODE_FLAG
import com.MAVLink.minimal.msg_heartbeat
import com.MAVLink.standard.msg_autopilot_version
import dolphin.mavlink.Autopilot
import dolphin.mavlink.Px4Modes
import groovy.transform.EqualsAndHashCode

/**
 * The frames of a vehicle that tell what it did, as one line each, in the order it sent them; a
 * frame that says what its kind said last is dropped (a heartbeat or MISSION_CURRENT repeats every
 * second), except an FTP reply, which answers a request of its own. Kinds: HEARTBEAT (armed, custom
 * mode), MISSION_CURRENT (seq, total, state), MISSION_ITEM_REACHED, EXTENDED_SYS_STATE (landed
 * state), COMMAND_ACK (command, result; not SET_MESSAGE_INTERVAL's), MISSION_ACK, the STATUSTEXTs in
 * {@link #TEXTS}, cut to those words, AUTOPILOT_VERSION (capabilities, version) and
 * FILE_TRANSFER_PROTOCOL (each reply whole: header, addressee, and the bytes it carries). A
 * QuadPlane's transition and VTOL landing texts are its stages, which the runtime follows; the
 * airspeeds, distances and heights they end with (QuadPlane::vtol_position_controller's v, d, sd, h,
 * dc) come from SITL's physics, so they are cut off. Not kept: "Reached waypoint" and "Passed
 * waypoint" (which of the two, and the distance, depend on the turn), "Mission: N" (it names every
 * item, also those MISSION_CURRENT never shows), "Throttle armed" and "Arming motors" (the arming's
 * ACK and heartbeat say it).
 *
 * <p>A PX4 vehicle's frames read as PX4's: its mode by name (AUTO.MISSION), its texts those in
 * {@link #PX4_TEXTS}, whole but for the tab PX4 ends each with (the runtime strips it too; the
 * simulator sends none), AUTOPILOT_VERSION its capabilities only (the measured build, untagged, said
 * version 0.0.0), MISSION_CURRENT without seq {@link #PX4_NO_CURRENT}.
 */
class KeyFrames {

    static final List<String> TEXTS = ['SIM Hit ground', 'Disarming motors', 'Mission complete, changing mode to RTL',
                                       'Mode change failed: Auto requires position', 'Bad alt frame', 'Internal Errors',
                                       'Transition started', 'Transition airspeed reached', 'Transition done',
                                       'VTOL approach', 'VTOL airbrake', 'VTOL position1', 'VTOL position2 started',
                                       'Land descend started', 'Land final started', 'Land complete', 'Throttle disarmed',
                                       'In landing sequence: mission reset', 'Mode change to Auto failed: runup not complete']

    /**
     * PX4's texts that tell what it did: arming, the landing and disarm, the mission's end, and a
     * refusal of the mission ("Geofence violation for waypoint N", CRITICAL, which the runtime fails the
     * mission on). Not kept: "Executing Mission", "Climb to N meters above home" and "Takeoff detected",
     * PX4's words for what the heartbeat, MISSION_CURRENT and the landed state say.
     */
    static final List<String> PX4_TEXTS = ['Armed by external command', 'Armed by mission start', 'Landing detected',
                                           'Mission finished, landed', 'Mission finished, loitering', 'Disarmed by landing',
                                           'Geofence violation for waypoint', 'Mission start denied']

    /**
     * PX4's MISSION_CURRENT seq between an upload and the navigator's first word on the new mission
     * (its current item -1), which goes out only when PX4's 1 Hz MISSION_CURRENT falls between them:
     * in px4-copter-fence-refused, not in the other recordings; left out.
     */
    static final int PX4_NO_CURRENT = 65535

    /** MAV_FTP_OPCODE names, of the requests a reply answers and of the reply itself. */
    static final Map<Integer, String> FTP_OPCODES = [0: 'None', 1: 'TerminateSession', 2: 'ResetSessions', 3: 'ListDirectory',
                                                     4: 'OpenFileRO', 5: 'ReadFile', 6: 'CreateFile', 7: 'WriteFile',
                                                     8: 'RemoveFile', 9: 'CreateDirectory', 10: 'RemoveDirectory',
                                                     11: 'OpenFileWO', 12: 'TruncateFile', 13: 'Rename',
                                                     14: 'CalcFileCRC32', 15: 'BurstReadFile', 128: 'ACK', 129: 'NAK']
    /** MAV_FTP_ERR names, of a NAK's first data byte. */
    static final List<String> FTP_ERRORS = ['None', 'Fail', 'FailErrno', 'InvalidDataSize', 'InvalidSession', 'NoSessionsAvailable',
                                            'EOF', 'UnknownCommand', 'FileExists', 'FileProtected', 'FileNotFound']
    static final int FTP_NAK = 129

    @EqualsAndHashCode
    static class Event {
        final String kind
        final String value

        Event(String kind, String value) {
            this.kind = kind
            this.value = value
        }

        @Override
        String toString() {
            "$kind $value"
        }
    }

    final List<Event> events = []
    private final Map<String, String> last = [:]
    private final Autopilot autopilot

    private KeyFrames(Autopilot autopilot) {
        this.autopilot = autopilot
    }

    /** The key frames of an ArduPilot vehicle, or of one running {@code autopilot}. */
    static KeyFrames of(List<MAVLinkMessage> messages, Autopilot autopilot = Autopilot.ARDUPILOT) {
        new KeyFrames(autopilot).tap { k -> messages.each { k.add(it) } }
    }

    void add(MAVLinkMessage m) {
        Event e = event(m)
        if (e != null && (e.kind == 'FILE_TRANSFER_PROTOCOL' || last[e.kind] != e.value)) {
            last[e.kind] = e.value
            events << e
        }
    }

    /** The lines of one kind, in order. */
    List<String> of(String kind) {
        events.findAll { it.kind == kind }*.toString()
    }

    List<String> lines() {
        events*.toString()
    }

    private Event event(MAVLinkMessage m) {
        boolean px4 = autopilot == Autopilot.PX4
        switch (m) {
            case msg_heartbeat:
                boolean armed = (m.base_mode & MAV_MODE_FLAG.MAV_MODE_FLAG_SAFETY_ARMED) != 0
                return new Event('HEARTBEAT', "armed=${armed ? 1 : 0} mode=${px4 ? Px4Modes.TABLE.name(m.custom_mode) : m.custom_mode}")
            case msg_mission_current:
                return px4 && m.seq == PX4_NO_CURRENT ? null : new Event('MISSION_CURRENT', "seq=${m.seq} total=${m.total} state=${m.mission_state}")
            case msg_mission_item_reached:
                return new Event('MISSION_ITEM_REACHED', "seq=${m.seq}")
            case msg_extended_sys_state:
                return new Event('EXTENDED_SYS_STATE', "landed_state=${m.landed_state}")
            case msg_command_ack:
                return m.command == MAV_CMD.MAV_CMD_SET_MESSAGE_INTERVAL ? null
                        : new Event('COMMAND_ACK', "command=${m.command} result=${m.result}")
            case msg_mission_ack:
                return new Event('MISSION_ACK', "type=${m.type}")
            case msg_statustext:
                String text = (px4 ? PX4_TEXTS : TEXTS).find { m.text.startsWith(it) }
                return text == null ? null : new Event('STATUSTEXT', px4 ? m.text.strip() : text)
            case msg_autopilot_version:
                return new Event('AUTOPILOT_VERSION', "capabilities=${m.capabilities}" + (px4 ? '' : " flight_sw_version=${m.flight_sw_version}"))
            case msg_file_transfer_protocol:
                return new Event('FILE_TRANSFER_PROTOCOL', ftp(m))
            default:
                return null
        }
    }

    /**
     * One FTP reply: its opcode (ACK or NAK), the request's, to whom, session, seq, size, offset,
     * burst_complete and its {@code size} data bytes: a NAK's as its MAV_FTP_ERR (and errno), an
     * ACK's in hex (the file size an OpenFileRO gives, the file bytes a read gives). The padding byte
     * and the data past {@code size} are no part of the reply.
     */
    private static String ftp(msg_file_transfer_protocol m) {
        short[] p = m.payload
        int opcode = p[3]
        int size = p[4]
        String line = "${name(opcode)} req=${name(p[5])} to=${m.target_system}/${m.target_component} session=${p[2]}" +
                " seq=${p[0] | p[1] << 8} size=${size} offset=${p[8] | p[9] << 8 | p[10] << 16 | (long) p[11] << 24}" +
                " burst_complete=${p[6]}"
        if (opcode == FTP_NAK) {
            return line + " error=${FTP_ERRORS[p[12]]}" + (size > 1 ? " errno=${p[13]}" : '')
        }
        line + ' data=' + (0..<size).collect { String.format('%02x', p[12 + it]) }.join('')
    }

    private static String name(int opcode) {
        FTP_OPCODES.getOrDefault(opcode, opcode as String)
    }
}
