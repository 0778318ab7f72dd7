package dolphin.sim

import com.MAVLink.Messages.MAVLinkMessage
import com.MAVLink.common.msg_command_ack
import com.MAVLink.common.msg_extended_sys_state
import com.MAVLink.common.msg_mission_ack
import com.MAVLink.common.msg_mission_current
import com.MAVLink.common.msg_mission_item_reached
import com.MAVLink.common.msg_statustext
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_MODE_FLAG
import com.MAVLink.minimal.msg_heartbeat
import groovy.transform.EqualsAndHashCode

/**
 * The frames of a vehicle that tell what it did, as one line each, in the order it sent them; a
 * frame that says what its kind said last is dropped (a heartbeat or MISSION_CURRENT repeats every
 * second). Kinds: HEARTBEAT (armed, custom mode), MISSION_CURRENT (seq, total, state),
 * MISSION_ITEM_REACHED, EXTENDED_SYS_STATE (landed state), COMMAND_ACK (command, result; not
 * SET_MESSAGE_INTERVAL's), MISSION_ACK, and the STATUSTEXTs in {@link #TEXTS}, cut to those words.
 */
class KeyFrames {

    static final List<String> TEXTS = ['SIM Hit ground', 'Disarming motors', 'Mission complete, changing mode to RTL',
                                       'Mode change failed: Auto requires position', 'Bad alt frame']

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

    static KeyFrames of(List<MAVLinkMessage> messages) {
        new KeyFrames().tap { k -> messages.each { k.add(it) } }
    }

    void add(MAVLinkMessage m) {
        Event e = event(m)
        if (e != null && last[e.kind] != e.value) {
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

    private static Event event(MAVLinkMessage m) {
        switch (m) {
            case msg_heartbeat:
                boolean armed = (m.base_mode & MAV_MODE_FLAG.MAV_MODE_FLAG_SAFETY_ARMED) != 0
                return new Event('HEARTBEAT', "armed=${armed ? 1 : 0} mode=${m.custom_mode}")
            case msg_mission_current:
                return new Event('MISSION_CURRENT', "seq=${m.seq} total=${m.total} state=${m.mission_state}")
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
                String text = TEXTS.find { m.text.startsWith(it) }
                return text == null ? null : new Event('STATUSTEXT', text)
            default:
                return null
        }
    }
}
