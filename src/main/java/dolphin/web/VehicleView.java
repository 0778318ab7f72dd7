package dolphin.web;

import java.util.List;

import com.MAVLink.enums.MAV_VTOL_STATE;
import dolphin.core.Position;
import dolphin.mavlink.VehicleState;
import dolphin.mission.transfer.TransferStatus;
import groovy.json.JsonOutput;

/**
 * What the page shows of one vehicle at one sample: where it is (null before its first position),
 * where it points, its Dolphin type, mode, arming, battery, home, the mission item it flies, whether
 * the script picked it, the last platform task on it, its payloads, its latest sensor readings,
 * where a mission transfer to or from it stands, and its link's health.
 *
 * @param vtol how a QuadPlane flies (hovering, to plane, plane, to hover: its MAV_VTOL_STATE), null for other vehicles
 * @param silence whole seconds the vehicle has been silent, -1 while it is heard
 * @param link the name of the link the vehicle is reached through ({@link LinkView#name()}), or null when not known
 */
record VehicleView(String id, String type, String family, String vtol, boolean connected, int silence, boolean picked, Position position,
                   double relativeAlt, double heading, String mode, boolean armed, int battery, Position home,
                   int item, int total, boolean fenceBreached, String task, List<String> payloads, List<Shown> readings,
                   TransferStatus transfer, String link) {

    /** A sensor reading as shown: stale ones are greyed out, not hidden, so a silent sensor is seen. */
    record Shown(String name, double value, String unit, int component, boolean fresh) {
    }

    VehicleView {
        payloads = List.copyOf(payloads);
        readings = List.copyOf(readings);
    }

    static VehicleView of(String id, String type, boolean connected, boolean picked, VehicleState s, String task) {
        return of(id, type, connected, -1, picked, s, task, List.of(), List.of(), null, null);
    }

    /** @param transfer where a mission transfer in progress stands, or null */
    static VehicleView of(String id, String type, boolean connected, int silence, boolean picked, VehicleState s, String task,
                          List<String> payloads, List<Shown> readings, TransferStatus transfer, String link) {
        return new VehicleView(id, type, s.kind(), vtolText(s.vtolState()), connected, silence, picked, s.position(), s.relativeAlt(), s.heading(),
                s.modeName(), s.armed(), s.batteryPercent(), s.home(), s.flyingMission() ? s.missionSeq() : -1, s.missionTotal(),
                s.fenceBreached(), task, payloads, readings, transfer, link);
    }

    /** MAV_VTOL_STATE in words; null for UNDEFINED, which every vehicle but a QuadPlane reports. */
    static String vtolText(int vtolState) {
        return switch (vtolState) {
            case MAV_VTOL_STATE.MAV_VTOL_STATE_MC -> "hovering";
            case MAV_VTOL_STATE.MAV_VTOL_STATE_TRANSITION_TO_FW -> "to plane";
            case MAV_VTOL_STATE.MAV_VTOL_STATE_FW -> "plane";
            case MAV_VTOL_STATE.MAV_VTOL_STATE_TRANSITION_TO_MC -> "to hover";
            default -> null;
        };
    }

    /**
     * The view as JSON (docs/embedding.md). Written directly rather than through a map: a thousand
     * vehicles are written four times a second (bench/README.md); strings go through Groovy's escaping.
     */
    String json() {
        StringBuilder b = new StringBuilder(320);
        b.append("{\"id\":").append(JsonOutput.toJson(id))
                .append(",\"type\":").append(JsonOutput.toJson(type))
                .append(",\"family\":").append(JsonOutput.toJson(family))
                .append(",\"vtol\":").append(JsonOutput.toJson(vtol))
                .append(",\"connected\":").append(connected)
                .append(",\"silence\":").append(silence < 0 ? "null" : String.valueOf(silence))
                .append(",\"picked\":").append(picked)
                .append(",\"position\":");
        point(b, position);
        b.append(",\"relativeAlt\":").append(round(relativeAlt, 10))
                .append(",\"heading\":").append(Double.isNaN(heading) ? "null" : String.valueOf(round(heading, 1)))
                .append(",\"mode\":").append(JsonOutput.toJson(mode))
                .append(",\"armed\":").append(armed)
                .append(",\"battery\":").append(battery < 0 ? "null" : String.valueOf(battery))
                .append(",\"home\":");
        point(b, home);
        return b.append(",\"item\":").append(item < 0 ? "null" : String.valueOf(item))
                .append(",\"total\":").append(total < 0 ? "null" : String.valueOf(total))
                .append(",\"fenceBreached\":").append(fenceBreached)
                .append(",\"task\":").append(JsonOutput.toJson(task))
                .append(",\"payloads\":").append(JsonOutput.toJson(payloads))
                .append(",\"readings\":").append(readingsJson())
                .append(",\"transfer\":").append(transferJson())
                .append(",\"link\":").append(JsonOutput.toJson(link))
                .append('}').toString();
    }

    private String transferJson() {
        if (transfer == null) {
            return "null";
        }
        return "{\"upload\":" + transfer.upload() + ",\"list\":" + JsonOutput.toJson(transfer.type().label())
                + ",\"path\":" + JsonOutput.toJson(transfer.path().label()) + ",\"done\":" + transfer.done()
                + ",\"total\":" + (transfer.total() < 0 ? "null" : String.valueOf(transfer.total()))
                + ",\"unit\":" + JsonOutput.toJson(transfer.unit()) + ",\"resends\":" + transfer.resends()
                + ",\"text\":" + JsonOutput.toJson(transfer.text()) + "}";
    }

    private String readingsJson() {
        if (readings.isEmpty()) {
            return "[]";
        }
        StringBuilder b = new StringBuilder("[");
        for (Shown r : readings) {
            b.append(b.length() > 1 ? "," : "").append("{\"name\":").append(JsonOutput.toJson(r.name()))
                    .append(",\"value\":").append(Double.isFinite(r.value()) ? String.valueOf(r.value()) : JsonOutput.toJson(String.valueOf(r.value())))
                    .append(",\"unit\":").append(JsonOutput.toJson(r.unit()))
                    .append(",\"component\":").append(r.component())
                    .append(",\"fresh\":").append(r.fresh()).append('}');
        }
        return b.append(']').toString();
    }

    /** [latitude, longitude, metres AMSL], or null: 1e-7 degrees (a centimetre) is what MAVLink carries. */
    private static void point(StringBuilder b, Position p) {
        if (p == null) {
            b.append("null");
        } else {
            b.append('[').append(round(p.latitudeDegrees(), 1e7)).append(',').append(round(p.longitudeDegrees(), 1e7))
                    .append(',').append(round(p.hae(), 10)).append(']');
        }
    }

    private static double round(double v, double scale) {
        return Math.round(v * scale) / scale;
    }
}
