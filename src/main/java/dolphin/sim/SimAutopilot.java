package dolphin.sim;

import com.MAVLink.common.msg_mission_current;
import com.MAVLink.enums.MAV_AUTOPILOT;
import com.MAVLink.enums.MAV_MODE_FLAG;
import com.MAVLink.enums.MAV_RESULT;
import com.MAVLink.enums.MISSION_STATE;
import com.MAVLink.standard.msg_autopilot_version;
import dolphin.mavlink.Autopilot;
import dolphin.mavlink.Px4Modes;
import dolphin.mission.model.Fence;
import dolphin.mission.model.MissionItem;
import java.util.List;
import java.util.OptionalInt;
import java.util.Locale;
import java.util.function.LongPredicate;

/**
 * The autopilot a simulated vehicle runs, beside its family's flight model ({@link VehicleKind}): what
 * differs on the wire between ArduPilot and PX4 (docs/mavlink.md, "Simulated PX4 vehicles"). The
 * heartbeat's autopilot, how DO_SET_MODE asks for a mode, how the mission is numbered (the vehicle
 * stores it with home as item 0 either way, and a PX4 vehicle leaves home out at the protocol's
 * edges), whether it checks the mission's feasibility, how MISSION_CURRENT reads, how often
 * MISSION_ITEM_REACHED is repeated, when STATUSTEXT goes out, and AUTOPILOT_VERSION. What its
 * firmware does differently in flight is the {@link Firmware} it makes of the family's.
 */
enum SimAutopilot {
    ARDUPILOT(Autopilot.ARDUPILOT, MAV_AUTOPILOT.MAV_AUTOPILOT_ARDUPILOTMEGA, 0) {
        @Override
        Firmware firmware(VehicleKind kind) {
            return kind.newFirmware();
        }

        @Override
        ItemStore missionList(MissionStore store) {
            return store;
        }

        /** Param2 is the whole custom_mode; FAILED when the mode is refused. */
        @Override
        int setMode(float param2, float param3, LongPredicate setter) {
            return setter.test((long) param2) ? MAV_RESULT.MAV_RESULT_ACCEPTED : MAV_RESULT.MAV_RESULT_FAILED;
        }

        /** GCS_MAVLINK::send_mission_current: total excludes home; mission_mode 1 in AUTO, else 0. */
        @Override
        msg_mission_current missionCurrent(int seq, int stored, int state, boolean paused, boolean inAuto, long id) {
            msg_mission_current c = new msg_mission_current();
            c.seq = seq;
            c.total = Math.max(0, stored - 1);
            c.mission_state = (short) state;
            c.mission_mode = (short) (inAuto ? 1 : 0);
            return c;
        }

        @Override
        boolean textsBeforeGcs() {
            return true;
        }

        @Override
        boolean feasible(List<MissionItem> items, Firmware firmware) {
            return true;
        }

        @Override
        msg_autopilot_version version(VehicleKind kind, boolean ftp) {
            return SimAutopilotVersion.message(kind, ftp);
        }
    },
    /** PX4 as its SITL (upstream main 752ecd3d1b) did, with its default parameters. */
    PX4(Autopilot.PX4, MAV_AUTOPILOT.MAV_AUTOPILOT_PX4, 10) {
        @Override
        Firmware firmware(VehicleKind kind) {
            return new Px4Firmware(kind.newFirmware());
        }

        @Override
        ItemStore missionList(MissionStore store) {
            return new Px4MissionList(store);
        }

        /**
         * Commander::handle_command: (uint8_t) param2 the main mode, (uint8_t) param3 the sub mode. A
         * whole custom_mode in param2 has main mode 0: ACCEPTED, and nothing changes. AUTO with sub mode 0
         * is AUTO.MISSION; a mode it does not enter is TEMPORARILY_REJECTED.
         */
        @Override
        int setMode(float param2, float param3, LongPredicate setter) {
            int main = (int) param2 & 0xff;
            int sub = (int) param3 & 0xff;
            if (main == 0) {
                return MAV_RESULT.MAV_RESULT_ACCEPTED;
            }
            if (main == Px4Modes.MAIN_AUTO && sub == 0) {
                sub = Px4Modes.AUTO_MISSION;
            }
            long mode = Px4Modes.customMode(main, main == Px4Modes.MAIN_AUTO ? sub : 0);
            return setter.test(mode) ? MAV_RESULT.MAV_RESULT_ACCEPTED : MAV_RESULT.MAV_RESULT_TEMPORARILY_REJECTED;
        }

        /**
         * MavlinkMissionManager::send_mission_current: seq without home; total the items, 65535 without a
         * mission (an infeasible one has its total, NO_MISSION); a mission left in the middle is PAUSED;
         * mission_mode 1 in AUTO.MISSION, else 2; mission_id the mission's CRC32, as its upload's MISSION_ACK.
         */
        @Override
        msg_mission_current missionCurrent(int seq, int stored, int state, boolean paused, boolean inAuto, long id) {
            msg_mission_current c = new msg_mission_current();
            boolean none = stored <= 1;
            c.seq = none ? 0 : Math.max(0, seq - 1);
            c.total = none ? 65535 : stored - 1;
            c.mission_id = id;
            c.mission_state = (short) (paused && state == MISSION_STATE.MISSION_STATE_NOT_STARTED
                    ? MISSION_STATE.MISSION_STATE_PAUSED : state);
            c.mission_mode = (short) (inAuto ? 1 : 2);
            return c;
        }

        /** STATUSTEXT's stream sends nothing until a ground station's heartbeat was heard (is_gcs_connected). */
        @Override
        boolean textsBeforeGcs() {
            return false;
        }

        @Override
        boolean feasible(List<MissionItem> items, Firmware firmware) {
            return Px4MissionCheck.feasible(items, firmware.family());
        }

        /** FeasibilityChecker: "Geofence violation for waypoint N", N its seq on PX4 plus one (the runtime's seq). */
        @Override
        OptionalInt outsideFence(List<MissionItem> items, Fence fence) {
            return Px4MissionCheck.outsideFence(items, fence);
        }


        @Override
        msg_autopilot_version version(VehicleKind kind, boolean ftp) {
            return SimAutopilotVersion.px4(ftp);
        }
    };

    private final Autopilot autopilot;
    private final int mavAutopilot;
    private final int reachedRepeats;

    SimAutopilot(Autopilot autopilot, int mavAutopilot, int reachedRepeats) {
        this.autopilot = autopilot;
        this.mavAutopilot = mavAutopilot;
        this.reachedRepeats = reachedRepeats;
    }

    /** The simulated autopilot of {@code autopilot}: ArduPilot or PX4. */
    static SimAutopilot of(Autopilot autopilot) {
        return switch (autopilot) {
            case ARDUPILOT -> ARDUPILOT;
            case PX4 -> PX4;
            case OTHER -> throw new IllegalArgumentException("the simulated fleet runs ArduPilot or PX4, not " + autopilot);
        };
    }

    /** The heartbeat's autopilot field. */
    int mavAutopilot() {
        return mavAutopilot;
    }

    /** How often MISSION_ITEM_REACHED is sent again, a second apart, after the first time. */
    int reachedRepeats() {
        return reachedRepeats;
    }

    /** A seq as the vehicle stores it (home 0) from one on the wire. */
    int storedSeq(int wireSeq) {
        return autopilot.missionSeq(wireSeq);
    }

    /** A seq on the wire from one as the vehicle stores it (home 0). */
    int wireSeq(int storedSeq) {
        return autopilot.vehicleSeq(storedSeq);
    }

    /** Whether MAV_CMD_MISSION_START arms the vehicle and sets its start item (PX4), rather than start the mission armed in AUTO. */
    boolean armsOnMissionStart() {
        return this == PX4;
    }

    /** Whether a new mission, uploaded while the vehicle does not fly one, starts again from its first item (PX4). */
    boolean restartsOnUpload() {
        return this == PX4;
    }

    /**
     * REQUEST_MESSAGE's result when the vehicle sends nothing back (a camera's or gimbal's information
     * without one, a message it does not send): ArduPilot's {@code arduPilots}, PX4's DENIED
     * (MavlinkReceiver::handle_request_message_command; its SITL denied CAMERA_INFORMATION and
     * GIMBAL_MANAGER_INFORMATION).
     */
    int notSent(int arduPilots) {
        return this == PX4 ? MAV_RESULT.MAV_RESULT_DENIED : arduPilots;
    }

    /** How its side of the mission protocol differs. */
    TransferRules transferRules() {
        return this == PX4 ? TransferRules.PX4 : TransferRules.ARDUPILOT;
    }

    /** Whether MAVLink FTP serves the mission as @MISSION files. */
    boolean missionFiles() {
        return autopilot.missionFtp();
    }

    @Override
    public String toString() {
        return autopilot.toString().toLowerCase(Locale.ROOT);
    }

    /** The firmware one vehicle of {@code kind} runs under this autopilot. */
    abstract Firmware firmware(VehicleKind kind);

    /** The mission list as the mission protocol transfers it. */
    abstract ItemStore missionList(MissionStore store);

    /**
     * MAV_CMD_DO_SET_MODE with MAV_MODE_FLAG_CUSTOM_MODE_ENABLED in param1: its MAV_RESULT; {@code setter}
     * changes to a custom mode, false when it refuses it.
     */
    abstract int setMode(float param2, float param3, LongPredicate setter);

    /**
     * MISSION_CURRENT of nav item {@code seq} as stored, {@code stored} items with home, {@code state} a
     * MISSION_STATE, {@code paused} when the mission stopped after it had begun, {@code id} the mission's
     * ({@link ItemStore#planId}).
     */
    abstract msg_mission_current missionCurrent(int seq, int stored, int state, boolean paused, boolean inAuto, long id);

    /** Whether STATUSTEXT goes out before a ground station's heartbeat was heard. */
    abstract boolean textsBeforeGcs();

    /** Whether the stored mission (home first) passes the autopilot's check once uploaded: else NO_MISSION. */
    abstract boolean feasible(List<MissionItem> items, Firmware firmware);

    /**
     * The first item of the stored mission (home first) outside the fence, numbered as the autopilot's
     * texts number it, for an autopilot that refuses such a mission once uploaded; empty otherwise.
     */
    OptionalInt outsideFence(List<MissionItem> items, Fence fence) {
        return OptionalInt.empty();
    }

    abstract msg_autopilot_version version(VehicleKind kind, boolean ftp);

    static boolean customModeFlag(float param1) {
        return ((int) param1 & MAV_MODE_FLAG.MAV_MODE_FLAG_CUSTOM_MODE_ENABLED) != 0;
    }
}
