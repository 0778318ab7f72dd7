package dolphin.cli;

import dolphin.mavlink.LinkHealth;
import dolphin.mavlink.MAVLinkNode;
import dolphin.mavlink.RadioStatus;
import dolphin.mavlink.VehicleState;
import dolphin.mission.flight.MissionService;
import dolphin.mission.transfer.TransferStatus;
import java.util.Locale;
import java.util.stream.Stream;

/**
 * What the status display shows of one vehicle at one moment: its mode, whether it is armed, its
 * battery and height above home, the mission item it flies, and the state of the script's task on it.
 * A silent vehicle shows how long it has been silent instead of its mode, a lost one LOST. Its link's
 * traffic and the telemetry radio on it show too (docs/guide.md, "Watching").
 *
 * @param silence whole seconds the vehicle has been silent (docs/guide.md, "Watching"), -1 while it is heard
 * @param battery percent, -1 when unknown
 * @param item the current mission item, 0 or less when none
 * @param task the last platform task on the vehicle and its state, or "" before the first
 * @param transfer where a mission transfer in progress stands ("uploading: 45 of 100 items, 3 resent"), or ""
 * @param link the health of the link the vehicle is reached through
 */
record VehicleStatus(String id, boolean connected, int silence, String mode, boolean armed, int battery, double altitude,
                     int item, int total, String task, String transfer, LinkHealth link) {

    static VehicleStatus of(MAVLinkNode node, String task) {
        VehicleState s = node.state();
        String transfer = MissionService.of(node.communications()).transferOn(node).map(TransferStatus::text).orElse("");
        int silence = node.silence().map(d -> (int) d.toSeconds()).orElse(-1);
        return new VehicleStatus(node.getId(), node.isConnected(), silence, s.modeName(), s.armed(), s.batteryPercent(),
                s.relativeAlt(), s.flyingMission() ? s.missionSeq() : 0, s.missionTotal(), task, transfer, node.linkHealth());
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

    /**
     * One line of prose, for logs. The radio's report and the link's rates come only where a radio
     * reports, and make no line of their own: a log of a fleet on a plain UDP link stays as it was.
     */
    String sentence() {
        return String.format(Locale.ROOT, "vehicle %s: %s%s, %s, battery %s, altitude %.1f m%s%s", id,
                connected && !silent() ? "" : modeText() + ", last seen ", mode, armed ? "armed" : "disarmed", batteryText(),
                altitude, item > 0 && total > 0 ? ", item " + item + " of " + total : "", task.isEmpty() ? "" : ", task " + task)
                + (transfer.isEmpty() ? "" : ", " + transfer)
                + (link.radio() == null ? "" : ", " + radioText() + " " + rateText());
    }

    static final String HEADER = String.format(Locale.ROOT, "%-8s %-16s %-8s %7s %9s %-9s %-12s %s",
            "vehicle", "mode", "armed", "battery", "altitude", "item", "link in/out", "task");

    /** One row of the live table, under {@link #HEADER}; the radio's report, when one came, at its end. */
    String row() {
        String tail = String.join(", ", Stream.of(task, transfer, link.radio() == null ? "" : radioText())
                .filter(t -> !t.isEmpty()).toList());
        return String.format(Locale.ROOT, "%-8s %-16s %-8s %7s %7.1f m %-9s %-12s %s", id, modeText(),
                armed ? "armed" : "disarmed", batteryText(), altitude, item > 0 && total > 0 ? item + "/" + total : "-",
                rateText(), tail);
    }

    /** The link's bytes each way, "1.2/3.4 kB/s": a tenth of a kilobyte below ten, whole ones above, so the column stays narrow. */
    String rateText() {
        return kilobytes(link.inBytesPerSecond()) + "/" + kilobytes(link.outBytesPerSecond()) + " kB/s";
    }

    /**
     * The radio's report, "radio -62/-65 dBm txbuf 97%" (local/remote signal, the local radio's free
     * transmit buffer), or "radio silent 12 s" once its last report is old news.
     */
    String radioText() {
        RadioStatus r = link.radio();
        if (!link.radioCurrent()) {
            return "radio silent " + link.radioAge().toSeconds() + " s";
        }
        return "radio " + dbm(r.rssiDbm()) + "/" + dbm(r.remrssiDbm()) + " dBm txbuf " + r.txbuf() + "%";
    }

    private static String kilobytes(double bytesPerSecond) {
        double k = bytesPerSecond / 1000;
        return String.format(Locale.ROOT, k < 9.95 ? "%.1f" : "%.0f", k);
    }

    private static String dbm(double value) {
        return Double.isNaN(value) ? "?" : String.valueOf(Math.round(value));
    }

    private String batteryText() {
        return battery < 0 ? "?" : battery + " %";
    }
}
