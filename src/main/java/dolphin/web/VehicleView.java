package dolphin.web;

import com.MAVLink.enums.MISSION_STATE;
import dolphin.core.Position;
import dolphin.mavlink.VehicleState;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * What the page shows of one vehicle at one sample: where it is (null before its first position),
 * where it points, its Dolphin type, mode, arming, battery, home, the mission item it flies, whether
 * the script picked it, and the last platform task on it.
 */
record VehicleView(String id, String type, String family, boolean connected, boolean picked, Position position,
                   double relativeAlt, double heading, String mode, boolean armed, int battery, Position home,
                   int item, int total, boolean fenceBreached, String task) {

    static VehicleView of(String id, String type, boolean connected, boolean picked, VehicleState s, String task) {
        // MISSION_CURRENT counts items during an upload too; only a mission being flown has an item to highlight.
        boolean flying = s.missionState() == MISSION_STATE.MISSION_STATE_ACTIVE || s.missionState() == MISSION_STATE.MISSION_STATE_PAUSED
                || s.missionState() == MISSION_STATE.MISSION_STATE_UNKNOWN && s.armed() && "AUTO".equals(s.modeName());
        return new VehicleView(id, type, s.family().label(), connected, picked, s.position(), s.relativeAlt(), s.heading(),
                s.modeName(), s.armed(), s.batteryPercent(), s.home(), flying ? s.missionSeq() : -1, s.missionTotal(),
                s.fenceBreached(), task);
    }

    Map<String, Object> json() {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("id", id);
        m.put("type", type);
        m.put("family", family);
        m.put("connected", connected);
        m.put("picked", picked);
        m.put("position", point(position));
        m.put("relativeAlt", round(relativeAlt, 10));
        m.put("heading", Double.isNaN(heading) ? null : round(heading, 1));
        m.put("mode", mode);
        m.put("armed", armed);
        m.put("battery", battery < 0 ? null : battery);
        m.put("home", point(home));
        m.put("item", item < 0 ? null : item);
        m.put("total", total < 0 ? null : total);
        m.put("fenceBreached", fenceBreached);
        m.put("task", task);
        return m;
    }

    /** [latitude, longitude, metres AMSL]: 1e-7 degrees (a centimetre) is what MAVLink carries. */
    static Object point(Position p) {
        return p == null ? null : java.util.List.of(round(p.latitudeDegrees(), 1e7), round(p.longitudeDegrees(), 1e7),
                round(p.hae(), 10));
    }

    private static double round(double v, double scale) {
        return Math.round(v * scale) / scale;
    }
}
