package dolphin.cli;

import dolphin.mavlink.MAVLinkNode;
import dolphin.mavlink.VehicleState;
import dolphin.mission.flight.MissionService;
import dolphin.mission.transfer.TransferStatus;
import java.util.Locale;

/**
 * What the status display shows of one vehicle at one moment: its mode, whether it is armed, its
 * battery and height above home, the mission item it flies, and the state of the script's task on it.
 * A silent vehicle shows how long it has been silent instead of its mode, a lost one LOST.
 *
 * @param silence whole seconds the vehicle has been silent (docs/guide.md, "Watching"), -1 while it is heard
 * @param battery percent, -1 when unknown
 * @param item the current mission item, 0 or less when none
 * @param task the last platform task on the vehicle and its state, or "" before the first
 * @param transfer where a mission transfer in progress stands ("uploading: 45 of 100 items, 3 resent"), or ""
 */
record VehicleStatus(String id, boolean connected, int silence, String mode, boolean armed, int battery, double altitude,
                     int item, int total, String task, String transfer) {

    static VehicleStatus of(MAVLinkNode node, String task) {
        VehicleState s = node.state();
        String transfer = MissionService.of(node.communications()).transferOn(node).map(TransferStatus::text).orElse("");
        int silence = node.silence().map(d -> (int) d.toSeconds()).orElse(-1);
        return new VehicleStatus(node.getId(), node.isConnected(), silence, s.modeName(), s.armed(), s.batteryPercent(),
                s.relativeAlt(), s.flyingMission() ? s.missionSeq() : 0, s.missionTotal(), task, transfer);
    }

    /**
     * The changes worth a line of their own in a log: everything but the battery, height, item and
     * transfer, and how long a silence lasts (its start and end are changes).
     */
    boolean sameEvent(VehicleStatus o) {
        return o != null && connected == o.connected && silent() == o.silent() && mode.equals(o.mode) && armed == o.armed
                && task.equals(o.task);
    }

    boolean silent() {
        return silence >= 0;
    }

    /** What the mode column shows: LOST after the connection timeout, before it how long the vehicle is silent, else the mode. */
    String modeText() {
        return !connected ? "LOST" : silent() ? "no contact " + silence + " s" : mode;
    }

    /** {@link #modeText()} without the seconds, to count vehicles by. */
    String modeGroup() {
        return !connected ? "LOST" : silent() ? "no contact" : mode;
    }

    /** One line of prose, for logs. */
    String sentence() {
        return String.format(Locale.ROOT, "vehicle %s: %s%s, %s, battery %s, altitude %.1f m%s%s", id,
                connected && !silent() ? "" : modeText() + ", last seen ", mode, armed ? "armed" : "disarmed", batteryText(),
                altitude, item > 0 && total > 0 ? ", item " + item + " of " + total : "", task.isEmpty() ? "" : ", task " + task)
                + (transfer.isEmpty() ? "" : ", " + transfer);
    }

    static final String HEADER = String.format(Locale.ROOT, "%-8s %-16s %-8s %7s %9s %-9s %s",
            "vehicle", "mode", "armed", "battery", "altitude", "item", "task");

    /** One row of the live table, under {@link #HEADER}. */
    String row() {
        return String.format(Locale.ROOT, "%-8s %-16s %-8s %7s %7.1f m %-9s %s", id, modeText(),
                armed ? "armed" : "disarmed", batteryText(), altitude, item > 0 && total > 0 ? item + "/" + total : "-", task)
                + (transfer.isEmpty() ? "" : (task.isEmpty() ? "" : ", ") + transfer);
    }

    private String batteryText() {
        return battery < 0 ? "?" : battery + " %";
    }
}
