package dolphin.mission.transfer;

import dolphin.mavlink.ProtocolTimers;
import dolphin.mission.model.MissionItem;
import dolphin.mission.model.MissionType;
import com.MAVLink.Messages.MAVLinkMessage;
import com.MAVLink.common.msg_mission_ack;
import com.MAVLink.common.msg_mission_count;
import com.MAVLink.common.msg_mission_request;
import com.MAVLink.common.msg_mission_request_int;
import com.MAVLink.enums.MAV_MISSION_RESULT;
import dolphin.mavlink.EnumNames;
import java.util.List;
import java.util.concurrent.CompletableFuture;

/**
 * Uploads a mission to one vehicle (MAVLink mission protocol; unlike the original it sends
 * MISSION_COUNT once, resends what is lost and fails on error ACKs instead of hanging:
 * docs/decisions.md, "Mission transfers"). MISSION_COUNT, sent again on timeout until the first request;
 * MISSION_REQUEST and MISSION_REQUEST_INT both answered with MISSION_ITEM_INT, again when repeated;
 * the last item sent again when the next request does not come; MISSION_ACK ACCEPTED after the
 * last item is success, any error ACK a failure naming the item, its command and the parameter.
 * INVALID_SEQUENCE ACKs are counted and ignored (ArduPilot sends them for duplicated items on noisy
 * links; it keeps going). Transfers of one vehicle run one at a time.
 */
public final class MissionUploadProtocol {

    private final MissionTransfers transfers;

    MissionUploadProtocol(MissionTransfers transfers) {
        this.transfers = transfers;
    }

    /** Uploads the items (item 0 is home; seq must equal the index); from any thread. */
    public CompletableFuture<TransferResult> upload(List<MissionItem> items) {
        return upload(items, transfers.config(), TransferProgress.NONE);
    }

    public CompletableFuture<TransferResult> upload(List<MissionItem> items, MissionTransferConfig config, TransferProgress progress) {
        return upload(MissionType.MISSION, items, config, progress);
    }

    /** Uploads a fence's or rally points' items (numbered from 0, no home), or a mission's; from any thread. */
    public CompletableFuture<TransferResult> upload(MissionType type, List<MissionItem> items) {
        return upload(type, items, transfers.config(), TransferProgress.NONE);
    }

    public CompletableFuture<TransferResult> upload(MissionType type, List<MissionItem> items, MissionTransferConfig config,
                                                    TransferProgress progress) {
        Upload u = new Upload(transfers.vehicle(), transfers.timers(), config, progress, type, List.copyOf(items));
        transfers.submit(u, u.items);
        return u.result;
    }

    /** Why a vehicle refused an item: "item 3 (NAV_WAYPOINT): MAV_MISSION_INVALID_PARAM7 (z = NaN)". */
    static String describe(int result, MissionItem item, int count) {
        String name = resultName(result);
        if (item == null) {
            return switch (result) {
                case MAV_MISSION_RESULT.MAV_MISSION_NO_SPACE -> name + " (the vehicle has no room for " + count + " items)";
                case MAV_MISSION_RESULT.MAV_MISSION_DENIED -> name + " (the vehicle accepts no mission transfer from us now;"
                        + " is another ground station uploading?)";
                default -> name + " (answering MISSION_COUNT " + count + ")";
            };
        }
        String detail = switch (result) {
            case MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED_FRAME -> "frame " + item.frameName() + " is not supported";
            case MAV_MISSION_RESULT.MAV_MISSION_UNSUPPORTED -> "command " + item.command() + " " + item.commandName()
                    + " is not supported";
            case MAV_MISSION_RESULT.MAV_MISSION_NO_SPACE -> "the vehicle has no room for " + count + " items";
            case MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM1 -> "param1 = " + item.param1();
            case MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM2 -> "param2 = " + item.param2();
            case MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM3 -> "param3 = " + item.param3();
            case MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM4 -> "param4 = " + item.param4();
            case MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM5_X -> "x = " + item.x() + " (latitude " + item.x() * 1e-7 + ")";
            case MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM6_Y -> "y = " + item.y() + " (longitude " + item.y() * 1e-7 + ")";
            case MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM7 -> "z = " + item.z();
            case MAV_MISSION_RESULT.MAV_MISSION_DENIED -> "the vehicle accepts no mission transfer from us now";
            case MAV_MISSION_RESULT.MAV_MISSION_OPERATION_CANCELLED -> "the vehicle cancelled the upload";
            default -> "frame " + item.frameName() + ", params " + item.param1() + ", " + item.param2() + ", " + item.param3()
                    + ", " + item.param4() + ", x " + item.x() + ", y " + item.y() + ", z " + item.z();
        };
        return "item " + item.seq() + " (" + item.commandName() + "): " + name + " (" + detail + ")";
    }

    static String resultName(int result) {
        return "MAV_MISSION_" + EnumNames.name(MAV_MISSION_RESULT.class, "MAV_MISSION_", result);
    }

    /** The state machine of one upload; communications thread only. */
    private static final class Upload extends Transfer {
        private final List<MissionItem> items;
        private boolean requested;      // a first request came: MISSION_COUNT is no longer sent
        private int tries;              // sends of the current message without progress
        private int lastSent = -1;      // the item last sent, named in errors
        private int highest = -1;       // the highest seq requested

        Upload(VehicleChannel vehicle, ProtocolTimers timers, MissionTransferConfig config, TransferProgress progress,
               MissionType type, List<MissionItem> items) {
            super(vehicle, timers, config, progress, type);
            this.items = items;
        }

        @Override
        String what() {
            return "upload to";
        }

        @Override
        void start() {
            for (int i = 0; i < items.size(); i++) {
                if (items.get(i).seq() != i) {
                    fail("item " + i + " has seq " + items.get(i).seq() + ": items must be numbered 0, 1, 2, ... in order");
                    return;
                }
            }
            sendCount();
        }

        private void sendCount() {
            msg_mission_count c = new msg_mission_count();
            c.target_system = (short) vehicle.system();
            c.target_component = (short) vehicle.component();
            c.count = items.size();
            c.mission_type = (short) type.wire();
            tries++;
            send(c);
            arm(this::countTimedOut);
        }

        private void countTimedOut() {
            if (tries >= tries()) {
                fail("no " + (items.isEmpty() ? "MISSION_ACK" : "MISSION_REQUEST") + " after " + sent(tries, "MISSION_COUNT"));
            } else {
                resends++;
                sendCount();
            }
        }

        private void sendItem(int seq) {
            lastSent = seq;
            tries++;
            send(items.get(seq).toMessage(vehicle.system(), vehicle.component(), type));
            arm(this::itemTimedOut);
        }

        /** The next request did not come: send the last item again (proactive resend). */
        private void itemTimedOut() {
            if (tries >= tries()) {
                MissionItem item = items.get(lastSent);
                String next = lastSent == items.size() - 1 ? "MISSION_ACK" : "MISSION_REQUEST for item " + (lastSent + 1);
                String hint = lastSent == items.size() - 1 ? "; the vehicle may hold the whole mission and its ACK was lost:"
                        + " download it to check" : "";
                fail("no " + next + " after item " + lastSent + " (" + item.commandName() + ") was sent " + tries
                        + (tries == 1 ? " time" : " times (" + config.timeoutText() + " apart)") + hint);
            } else {
                resends++;
                sendItem(lastSent);
            }
        }

        @Override
        void handle(MAVLinkMessage message) {
            if (message instanceof msg_mission_request r) {
                request(r.seq);
            } else if (message instanceof msg_mission_request_int r) {
                request(r.seq);
            } else if (message instanceof msg_mission_ack a) {
                ack(a.type);
            }
        }

        private void request(int seq) {
            if (seq < 0 || seq >= items.size()) {
                fail("the vehicle requested item " + seq + " but the " + type.label() + " has " + items.size() + " items (0 to "
                        + (items.size() - 1) + ")");
                return;
            }
            requested = true;
            if (seq == lastSent) {
                resends++;      // asked again: the item was lost; keep counting tries (no progress)
            } else {
                tries = 0;
            }
            if (seq > highest) {
                highest = seq;
                report(seq, items.size());
            }
            sendItem(seq);
        }

        private void ack(int result) {
            if (result == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED) {
                if (items.isEmpty() || (requested && highest == items.size() - 1)) {
                    report(items.size(), items.size());
                    succeed(items);
                } else if (!requested) {
                    ignoredAcks++;      // a late ACK of an earlier transfer
                } else {
                    fail("the vehicle accepted the " + type.label() + " after requesting only items 0 to " + highest + " of "
                            + items.size());
                }
            } else if (result == MAV_MISSION_RESULT.MAV_MISSION_INVALID_SEQUENCE) {
                ignoredAcks++;          // a duplicated or reordered item on a noisy link; the vehicle keeps going
            } else {
                fail(describe(result, lastSent < 0 ? null : items.get(lastSent), items.size()));
            }
        }
    }
}
