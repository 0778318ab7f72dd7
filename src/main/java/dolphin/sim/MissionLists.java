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
import dolphin.mission.model.Fence;
import dolphin.mission.model.MissionType;
import dolphin.mission.model.RallyPoints;

/**
 * A simulated vehicle's three lists (mission, fence, rally points) and a mission-protocol transfer
 * for each, with the mission protocol's messages routed by their mission_type; a type we do not
 * keep goes to the mission's transfer, which answers UNSUPPORTED.
 */
final class MissionLists {

    private final MissionItemProtocol mission;
    private final MissionItemProtocol fence;
    private final MissionItemProtocol rally;
    private final MissionStore missionStore;
    private final AirspaceStore fenceStore;
    private final AirspaceStore rallyStore;

    /** {@code missionList}: the mission as the protocol transfers it, {@code missionStore} as the vehicle stores it. */
    MissionLists(ItemStore missionList, MissionStore missionStore, int capacity, MissionItemProtocol.Host host, TransferRules rules) {
        this.missionStore = missionStore;
        this.fenceStore = new AirspaceStore(MissionType.FENCE, capacity);
        this.rallyStore = new AirspaceStore(MissionType.RALLY, capacity);
        this.mission = new MissionItemProtocol(missionList, host, rules);
        this.fence = new MissionItemProtocol(fenceStore, host, rules);
        this.rally = new MissionItemProtocol(rallyStore, host, rules);
    }

    /** Handles a mission-protocol message addressed to {@code sysid}; false if it is not one. */
    boolean handle(MAVLinkMessage m, int sysid, long now) {
        int[] target = target(m);
        if (target == null || target[0] != sysid) {
            return false;
        }
        MissionType type = MissionType.of(target[1]);
        MissionItemProtocol t = type == MissionType.FENCE ? fence : type == MissionType.RALLY ? rally : mission;
        t.handle(m, now);
        return true;
    }

    void tick(long now) {
        mission.tick(now);
        fence.tick(now);
        rally.tick(now);
    }

    boolean uploading() {
        return mission.uploading() || fence.uploading() || rally.uploading();
    }

    /** The list of a type, as MAVLink FTP's @MISSION files reach it. */
    ItemStore store(MissionType type) {
        return switch (type) {
            case MISSION -> missionStore;
            case FENCE -> fenceStore;
            case RALLY -> rallyStore;
        };
    }

    /** The stored fence (checked when its upload completed). */
    Fence fence() {
        return fenceStore.fence();
    }

    RallyPoints rally() {
        return rallyStore.rally();
    }

    /** {target_system, mission_type} of a mission-protocol message, or null for another message. */
    private static int[] target(MAVLinkMessage m) {
        if (m instanceof msg_mission_count x) {
            return new int[] {x.target_system, x.mission_type};
        } else if (m instanceof msg_mission_item_int x) {
            return new int[] {x.target_system, x.mission_type};
        } else if (m instanceof msg_mission_item x) {
            return new int[] {x.target_system, x.mission_type};
        } else if (m instanceof msg_mission_request_list x) {
            return new int[] {x.target_system, x.mission_type};
        } else if (m instanceof msg_mission_request_int x) {
            return new int[] {x.target_system, x.mission_type};
        } else if (m instanceof msg_mission_request x) {
            return new int[] {x.target_system, x.mission_type};
        } else if (m instanceof msg_mission_clear_all x) {
            return new int[] {x.target_system, x.mission_type};
        } else if (m instanceof msg_mission_ack x) {
            return new int[] {x.target_system, x.mission_type};
        }
        return null;
    }
}
