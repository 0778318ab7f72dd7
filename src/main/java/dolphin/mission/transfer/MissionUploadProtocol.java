package dolphin.mission.transfer;

import dolphin.mavlink.Autopilot;
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
import java.time.Duration;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;

/**
 * Uploads a mission to one vehicle (MAVLink mission protocol; unlike the original it sends
 * MISSION_COUNT once, resends what is lost and fails on error ACKs instead of hanging:
 * docs/decisions.md, "Mission transfers" and "Transfers on lossy links"). MISSION_COUNT, sent again
 * on timeout until the first request; MISSION_REQUEST and MISSION_REQUEST_INT both answered with
 * MISSION_ITEM_INT, again when repeated; items k and k + 1 sent again when the request after k
 * does not come; MISSION_ACK ACCEPTED after the last item is success, any error ACK a failure
 * naming the item, its command and the parameter, but a MAV_MISSION_ERROR after the last item, or
 * silence until the give-up, is settled by reading the list back. INVALID_SEQUENCE ACKs are counted
 * and ignored (ArduPilot sends them for items it already has; it keeps going). Timeouts follow the
 * link's round trip; the upload gives up after a time without progress. Transfers of one vehicle
 * run one at a time.
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
        var autopilot = transfers.vehicle().autopilot();
        Upload u = new Upload(transfers.vehicle(), transfers.timers(), config, progress, type,
                List.copyOf(AutopilotLists.toVehicle(autopilot, type, items)), AutopilotLists.offset(autopilot, type));
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

    /**
     * The state machine of one upload; communications thread only. Stop-and-wait, each item sent
     * when the vehicle requests it; when the request after item k does not come within the
     * timeout, items k and k + 1 go again (ArduPilot accepts an item whose seq is the one it
     * expects, requested or not): whichever of item k or the request for k + 1 was lost, the
     * vehicle moves on within one round trip. A request for that k + 1 arriving while it is still
     * in flight (sent less than one timeout ago) is not answered, once: the timer resends if the
     * request for k + 2 does not follow, a repeated request at once.
     */
    private static final class Upload extends Transfer {
        /**
         * ArduPilot asks again for the item it awaits after 1 s without one: an answer later than that
         * may answer its own repetition, not our message, and is no sample (Karn's rule, both ways).
         */
        private static final long VEHICLE_REPEAT_NANOS = 1_000_000_000L;

        private final List<MissionItem> items;
        /** How many items the runtime's list has before the vehicle's first, for naming items the runtime's way. */
        private final int offset;
        private final int[] sends;      // sends of each item
        private final long[] sentAt;    // when each item was last sent
        private int countSends;
        private long countAt;
        private int highest = -1;       // the highest seq requested: the vehicle holds the items before it
        private int lastSent = -1;      // the item last sent, named in errors
        private int ahead = -1;         // the item sent before its request by the recovery, until answered
        private MissionDownloadProtocol.Download readBack;  // settles a lost final ACK
        private String unsettled;       // the error the read-back settles
        private boolean earlyErrorIgnored;  // a MAV_MISSION_ERROR before any request was taken for a late one

        Upload(VehicleChannel vehicle, ProtocolTimers timers, MissionTransferConfig config, TransferProgress progress,
               MissionType type, List<MissionItem> items, int offset) {
            super(vehicle, timers, config, progress, type);
            this.items = items;
            this.offset = offset;
            this.sends = new int[items.size()];
            this.sentAt = new long[items.size()];
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

        /** The item as the runtime numbers it, for an error's text. */
        private MissionItem named(MissionItem item) {
            return item.withSeq(item.seq() + offset);
        }

        private void sendCount() {
            msg_mission_count c = new msg_mission_count();
            c.target_system = (short) vehicle.system();
            c.target_component = (short) vehicle.component();
            c.count = items.size();
            c.mission_type = (short) type.wire();
            countSends++;
            countAt = timers.nanoTime();
            send(c);
            arm(this::countTimedOut);
        }

        private void countTimedOut() {
            if (!patient()) {
                fail(waited(items.isEmpty() ? "MISSION_ACK" : "MISSION_REQUEST for item 0", "MISSION_COUNT", countSends));
            } else {
                backOff();
                resends++;
                sendCount();
            }
        }

        private void sendItem(int seq) {
            if (sends[seq] > 0) {
                resends++;
            }
            sends[seq]++;
            sentAt[seq] = timers.nanoTime();
            lastSent = seq;
            send(items.get(seq).toMessage(vehicle.system(), vehicle.component(), type));
        }

        /** No request after item {@code highest} in time: it or the request was lost; send it and the next. */
        private void itemTimedOut() {
            int last = items.size() - 1;
            if (!patient()) {
                String awaited = highest == last ? "MISSION_ACK" : "MISSION_REQUEST for item " + (highest + 1);
                String reason = waited(awaited, "item " + highest, sends[highest]);
                if (sends[last] > 0) {
                    settle(reason);
                } else {
                    fail(reason);
                }
                return;
            }
            backOff();
            sendItem(highest);
            if (highest < last) {
                sendItem(highest + 1);
                ahead = highest + 1;
            }
            arm(this::itemTimedOut);
        }

        @Override
        void handle(MAVLinkMessage message) {
            if (readBack != null) {
                if (message instanceof msg_mission_ack a && a.type == MAV_MISSION_RESULT.MAV_MISSION_ERROR) {
                    ignoredAcks++;      // another repeated last item, answered after the vehicle finished
                } else {
                    readBack.handle(message);
                }
            } else if (message instanceof msg_mission_request r) {
                request(r.seq);
            } else if (message instanceof msg_mission_request_int r) {
                request(r.seq);
            } else if (message instanceof msg_mission_ack a) {
                ack(a);
            }
        }

        private void request(int seq) {
            if (seq < 0 || seq >= items.size()) {
                fail("the vehicle requested item " + seq + " but the " + type.label() + " has " + items.size() + " items (0 to "
                        + (items.size() - 1) + ")");
                return;
            }
            if (seq < highest) {
                return;                 // stale (reordered or late): the vehicle asked for a later item since
            }
            if (seq > highest) {
                if (highest < 0 && countSends == 1) {
                    cleanSample(countAt);
                } else if (seq > 0 && sends[seq - 1] == 1) {
                    cleanSample(sentAt[seq - 1]);
                }
                advanced();
                highest = seq;
                report(seq, items.size());
            }
            if (seq == ahead) {
                ahead = -1;             // deferred once: a repeated request means the vehicle lost it
                long left = sentAt[seq] + timeout().toNanos() - timers.nanoTime();
                if (left > 0) {         // in flight: wait for the request of the next one
                    arm(Duration.ofNanos(left), this::itemTimedOut);
                    return;
                }
            }
            ahead = -1;
            sendItem(seq);              // again at once when asked again: the vehicle lost it
            arm(this::itemTimedOut);
        }

        private void ack(msg_mission_ack a) {
            int result = a.type;
            int last = items.size() - 1;
            if (result == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED) {
                planId = a.opaque_id;
                if (items.isEmpty()) {
                    if (countSends == 1) {
                        cleanSample(countAt);
                    }
                    report(0, 0);
                    succeed(items);
                } else if (highest < 0) {
                    ignoredAcks++;      // a late ACK of an earlier transfer
                } else if (sends[last] > 0) {
                    if (sends[last] == 1) {
                        cleanSample(sentAt[last]);
                    }
                    report(items.size(), items.size());
                    succeed(items);
                } else {
                    fail("the vehicle accepted the " + type.label() + " after requesting only items 0 to " + highest + " of "
                            + items.size());
                }
            } else if (result == MAV_MISSION_RESULT.MAV_MISSION_INVALID_SEQUENCE) {
                ignoredAcks++;          // an item it already had (a duplicate, or the recovery's item k): it keeps going
            } else if (result == MAV_MISSION_RESULT.MAV_MISSION_ERROR && highest < 0 && !earlyErrorIgnored) {
                // before any request, the first may answer an item of the previous upload still crossing a
                // slow link (ArduPilot's answer to an item when no upload is in progress); a second one is ours
                earlyErrorIgnored = true;
                ignoredAcks++;
            } else if (result == MAV_MISSION_RESULT.MAV_MISSION_ERROR && last >= 0 && sends[last] > 0) {
                // ArduPilot's answer to an item when no upload is in progress: the last item repeated after a lost
                // final ACK, or a refused last item; reading the list back tells which
                settle(describe(result, named(items.get(last)), items.size()));
            } else {
                fail(describe(result, lastSent < 0 ? null : named(items.get(lastSent)), items.size()));
            }
        }

        /** The answer to a message sent once (Karn), if it came before the vehicle would have repeated its own message. */
        private void cleanSample(long sentAt) {
            if (timers.nanoTime() - sentAt < VEHICLE_REPEAT_NANOS) {
                sample(sentAt);
            }
        }

        /** Downloads the list, in this same transfer, to learn whether the vehicle holds it all. */
        private void settle(String error) {
            disarm();
            unsettled = error;
            readBack = new MissionDownloadProtocol.Download(vehicle, timers, config, progress, type);
            readBack.begin(this::settled);
        }

        private void settled() {
            TransferResult back = readBack.result.join();
            resends += readBack.resends;
            ignoredAcks += readBack.ignoredAcks;
            if (!back.success()) {
                fail(unsettled + "; reading the " + type.label() + " back failed: " + readBack.reason());
                return;
            }
            // both as the runtime numbers them, compared by what the vehicle's autopilot keeps, as the executor's verification does
            Autopilot autopilot = vehicle.autopilot();
            Optional<String> difference = MissionVerification.firstDifference(autopilot, type,
                    AutopilotLists.fromVehicle(autopilot, type, items, vehicle.home()),
                    AutopilotLists.fromVehicle(autopilot, type, back.items(), vehicle.home()));
            if (difference.isPresent()) {
                fail(unsettled + "; read back, " + difference.get());
            } else {
                report(items.size(), items.size());
                planId = back.planId();
                succeedVerified(items, "the final ACK was lost; the vehicle holds the whole " + type.label() + ", read back");
            }
        }
    }
}
