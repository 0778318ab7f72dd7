package dolphin.sim;

import com.MAVLink.Messages.MAVLinkMessage;
import com.MAVLink.common.msg_mission_ack;
import com.MAVLink.common.msg_mission_clear_all;
import com.MAVLink.common.msg_mission_count;
import com.MAVLink.common.msg_mission_item;
import com.MAVLink.common.msg_mission_item_int;
import com.MAVLink.common.msg_mission_request;
import com.MAVLink.common.msg_mission_request_int;
import com.MAVLink.common.msg_mission_request_list;
import com.MAVLink.enums.MAV_MISSION_RESULT;
import com.MAVLink.enums.MAV_SEVERITY;
import dolphin.mission.model.MissionItem;
import dolphin.mission.transfer.StoredItems;
import dolphin.mission.model.MissionType;

/**
 * The vehicle side of the mission protocol, as ArduPilot's MissionItemProtocol does it: uploads
 * (MISSION_COUNT truncates at once; items are asked for with MISSION_REQUEST, id 40, re-asked once more
 * than a second passed since the last request, cancelled once more than 8 s passed without an item; a
 * wrong seq is INVALID_SEQUENCE and the upload goes on; an item from another sender, or a download,
 * during an upload is DENIED; an item when no upload is in progress, such as the last one repeated
 * after its ACK was lost, is ERROR, as GCS_MAVLINK::handle_mission_item answers; a DO_JUMP to item 0 or
 * past the uploaded count is ERROR and ends the upload), downloads (MISSION_REQUEST_LIST,
 * MISSION_REQUEST_INT answered with MISSION_ITEM_INT, MISSION_REQUEST with MISSION_ITEM) and
 * MISSION_CLEAR_ALL. One transfer a list (mission, fence, rally points: {@link ItemStore}), as
 * ArduPilot has one MissionItemProtocol a mission_type; a message of another mission_type is
 * UNSUPPORTED. Where PX4 differs ({@link TransferRules}: its times, an item again after the end
 * ACCEPTED, a wrong seq ignored), it follows its autopilot's rules. Runs on the fleet's thread, under
 * the vehicle's lock.
 */
final class MissionItemProtocol {


    /** What the transfer needs from its vehicle. */
    interface Host {
        void send(MAVLinkMessage m);

        void text(int severity, String text);

        /** False while armed and flying a mission in AUTO: clearing is refused then. */
        boolean clearAllowed();

        /** The stored list changed (an upload finished, or it was cleared). */
        void changed(MissionType type);
    }

    private final ItemStore store;
    private final MissionType type;
    private final Host host;
    private final TransferRules rules;
    private boolean uploading;
    /** The item count of the last upload completed; -1 once another transfer began. */
    private int completed = -1;
    private int uploaderSys;
    private int uploaderComp;
    private int expected;
    private int next;
    private long lastItem;
    private long lastRequest;
    private boolean floatWarned;
    /** The list's id when the upload began: an autopilot with ids (PX4) takes a list again only when it changed. */
    private long idBefore;

    MissionItemProtocol(ItemStore store, Host host, TransferRules rules) {
        this.store = store;
        this.type = store.type();
        this.host = host;
        this.rules = rules;
    }

    boolean uploading() {
        return uploading;
    }

    /** Handles a mission message addressed to this vehicle; false if it is not one. */
    boolean handle(MAVLinkMessage m, long now) {
        if (m instanceof msg_mission_count c) {
            count(c, now);
        } else if (m instanceof msg_mission_item_int i) {
            item(i.sysid, i.compid, i.mission_type, MissionItem.fromMessage(i), now);
        } else if (m instanceof msg_mission_item i) {
            if (!floatWarned) {
                floatWarned = true;
                host.text(MAV_SEVERITY.MAV_SEVERITY_WARNING, "got MISSION_ITEM; GCS should send MISSION_ITEM_INT");
            }
            item(i.sysid, i.compid, i.mission_type, fromFloat(i, type), now);
        } else if (m instanceof msg_mission_request_list r) {
            if (refuseDownload(r.sysid, r.compid, r.mission_type)) {
                return true;
            }
            completed = -1;
            msg_mission_count c = new msg_mission_count();
            c.count = store.count();
            c.opaque_id = store.planId();
            c.mission_type = (short) type.wire();
            c.target_system = (short) r.sysid;
            c.target_component = (short) r.compid;
            host.send(c);
        } else if (m instanceof msg_mission_request_int r) {
            if (!refuseDownload(r.sysid, r.compid, r.mission_type) && inRange(r.sysid, r.compid, r.seq)) {
                host.send(store.reported(r.seq).toMessage(r.sysid, r.compid, type));
            }
        } else if (m instanceof msg_mission_request r) {
            if (!refuseDownload(r.sysid, r.compid, r.mission_type) && inRange(r.sysid, r.compid, r.seq)) {
                host.send(toFloat(store.reported(r.seq), r.sysid, r.compid, type));
            }
        } else if (m instanceof msg_mission_clear_all c) {
            clear(c);
        } else {
            return m instanceof msg_mission_ack; // the end of a download: nothing to do
        }
        return true;
    }

    /**
     * Re-requests the pending item once more than a second passed since the last request; cancels
     * the upload once more than 8 s passed without an item (MissionItemProtocol::update compares
     * with {@code >}; the fleet's 50 ms ticks make these 1.05 s and 8.05 s); PX4's times are its own.
     */
    void tick(long now) {
        if (!uploading) {
            return;
        }
        if (now - lastItem > rules.timeoutNanos()) {
            uploading = false;
            ack(uploaderSys, uploaderComp, MAV_MISSION_RESULT.MAV_MISSION_OPERATION_CANCELLED);
            host.text(MAV_SEVERITY.MAV_SEVERITY_WARNING, rules.timeoutText());
            host.changed(type);
        } else if (now - lastRequest > rules.resendNanos()) {
            request(now);
        }
    }

    private void count(msg_mission_count c, long now) {
        if (c.mission_type != type.wire()) {
            ack(c.sysid, c.compid, MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED, c.mission_type);
            return;
        }
        if (uploading && !fromUploader(c.sysid, c.compid)) {
            ack(c.sysid, c.compid, MAV_MISSION_RESULT.MAV_MISSION_DENIED);
            return;
        }
        uploading = false;
        idBefore = store.planId();
        if (c.count > store.capacity()) {
            ack(c.sysid, c.compid, MAV_MISSION_RESULT.MAV_MISSION_NO_SPACE);
            return;
        }
        store.truncate(c.count);
        if (c.count == 0) {
            ack(c.sysid, c.compid, MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED);
            host.changed(type);
            return;
        }
        uploading = true;
        completed = -1;
        uploaderSys = c.sysid;
        uploaderComp = c.compid;
        expected = c.count;
        next = 0;
        lastItem = now;
        request(now);
    }

    private void item(int sys, int comp, int missionType, MissionItem item, long now) {
        if (missionType != type.wire()) {
            ack(sys, comp, MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED, missionType);
            return;
        }
        if (!uploading) {
            boolean lastAgain = rules.lastItemAgainAccepted() && item.seq() == completed - 1;
            ack(sys, comp, lastAgain ? MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED : MAV_MISSION_RESULT.MAV_MISSION_ERROR);
            return;
        }
        // ArduPilot checks the seq before the sender
        if (item.seq() != next) {
            if (!rules.wrongSeqIgnored()) {
                ack(sys, comp, MAV_MISSION_RESULT.MAV_MISSION_INVALID_SEQUENCE);
            }
            return;
        }
        if (!fromUploader(sys, comp)) {
            ack(sys, comp, MAV_MISSION_RESULT.MAV_MISSION_DENIED);
            return;
        }
        int result = store.check(item);
        if (result == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED && store.jumpsNowhere(item, Math.max(store.count(), expected))) {
            result = MAV_MISSION_RESULT.MAV_MISSION_ERROR;
        }
        if (result != MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED) {
            uploading = false;
            ack(sys, comp, result);
            host.changed(type);
            return;
        }
        store.put(item);
        lastItem = now;
        next++;
        if (next < expected) {
            request(now);
            return;
        }
        uploading = false;
        result = store.complete();
        boolean accepted = result == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED;
        completed = accepted ? expected : -1;
        long id = accepted ? store.planId() : 0;
        ack(sys, comp, result, type.wire(), id);
        store.receivedText().ifPresent(t -> host.text(MAV_SEVERITY.MAV_SEVERITY_INFO, t));
        // PX4 takes the list only when its CRC changed (MavlinkMissionManager): the same mission again stays as it was
        if (id == 0 || id != idBefore) {
            host.changed(type);
        }
    }

    private void clear(msg_mission_clear_all c) {
        if (c.mission_type != type.wire()) {
            ack(c.sysid, c.compid, MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED, c.mission_type);
            return;
        }
        if (uploading || (type == MissionType.MISSION && !host.clearAllowed())) {
            ack(c.sysid, c.compid, uploading ? MAV_MISSION_RESULT.MAV_MISSION_DENIED : MAV_MISSION_RESULT.MAV_MISSION_ERROR);
            return;
        }
        store.clear();
        ack(c.sysid, c.compid, MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED);
        host.changed(type);
    }

    private boolean refuseDownload(int sys, int comp, int missionType) {
        if (missionType != type.wire()) {
            ack(sys, comp, MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED, missionType);
            return true;
        }
        if (uploading) {
            ack(sys, comp, MAV_MISSION_RESULT.MAV_MISSION_DENIED);
            return true;
        }
        return false;
    }

    private boolean inRange(int sys, int comp, int seq) {
        if (seq < 0 || seq >= store.count()) {
            ack(sys, comp, MAV_MISSION_RESULT.MAV_MISSION_INVALID_SEQUENCE);
            return false;
        }
        return true;
    }

    private boolean fromUploader(int sys, int comp) {
        return sys == uploaderSys && comp == uploaderComp;
    }

    private void request(long now) {
        msg_mission_request r = new msg_mission_request();
        r.seq = next;
        r.mission_type = (short) type.wire();
        r.target_system = (short) uploaderSys;
        r.target_component = (short) uploaderComp;
        host.send(r);
        lastRequest = now;
    }

    private void ack(int sys, int comp, int result) {
        ack(sys, comp, result, type.wire());
    }

    private void ack(int sys, int comp, int result, int missionType) {
        ack(sys, comp, result, missionType, 0);
    }

    private void ack(int sys, int comp, int result, int missionType, long planId) {
        msg_mission_ack a = new msg_mission_ack();
        a.type = (short) result;
        a.opaque_id = planId;
        a.mission_type = (short) missionType;
        a.target_system = (short) sys;
        a.target_component = (short) comp;
        host.send(a);
    }

    private static MissionItem fromFloat(msg_mission_item i, MissionType type) {
        boolean positional = type != MissionType.MISSION || StoredItems.POSITIONAL.contains(i.command);
        int x = positional ? clampE7(i.x) : Math.round(i.x);
        int y = positional ? clampE7(i.y) : Math.round(i.y);
        return new MissionItem(i.seq, i.command, i.frame, i.param1, i.param2, i.param3, i.param4, x, y, i.z,
                i.autocontinue != 0);
    }

    private static int clampE7(float degrees) {
        double e7 = degrees * 1e7;
        return Double.isFinite(e7) ? (int) Math.max(Integer.MIN_VALUE, Math.min(Integer.MAX_VALUE, Math.round(e7)))
                : Integer.MAX_VALUE;
    }

    private static msg_mission_item toFloat(MissionItem item, int sys, int comp, MissionType type) {
        msg_mission_item m = new msg_mission_item();
        boolean positional = type != MissionType.MISSION || StoredItems.POSITIONAL.contains(item.command())
                || item.seq() == 0;
        m.target_system = (short) sys;
        m.target_component = (short) comp;
        m.seq = item.seq();
        m.command = item.command();
        m.frame = (short) item.frame();
        m.param1 = item.param1();
        m.param2 = item.param2();
        m.param3 = item.param3();
        m.param4 = item.param4();
        m.x = positional ? (float) (item.x() * 1e-7) : item.x();
        m.y = positional ? (float) (item.y() * 1e-7) : item.y();
        m.z = item.z();
        m.autocontinue = (short) (item.autocontinue() ? 1 : 0);
        m.mission_type = (short) type.wire();
        return m;
    }
}
