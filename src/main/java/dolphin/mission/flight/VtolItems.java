package dolphin.mission.flight;

import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_FRAME;
import dolphin.core.Position;
import dolphin.mission.model.FlightWay;
import dolphin.mission.model.MissionItem;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * A QuadPlane's mission as ArduPlane must receive it (docs/vtol.md, "Take-off and landing"):
 *
 * <ul>
 * <li>a take-off or a landing left to the vehicle, or said to be vertical, becomes NAV_VTOL_TAKEOFF or
 *     NAV_VTOL_LAND, whatever the vehicle's Q_OPTIONS make of NAV_TAKEOFF and NAV_LAND. NAV_VTOL_TAKEOFF's
 *     height is a climb above where the vehicle stands (QuadPlane::do_vtol_takeoff), so the take-off's
 *     height above home;</li>
 * <li>one said to be on a runway stays NAV_TAKEOFF or NAV_LAND, which a QuadPlane flies on its wings only
 *     if its Q_OPTIONS allow it (bit 1, bit 2: QuadPlane::is_vtol_takeoff, is_vtol_land); if not, the
 *     mission is refused before upload;</li>
 * <li>a landing whose navigation item before is a waypoint too near for the vehicle to slow down from
 *     its landing airspeed gets an approach leg first ({@link #approach}). ArduPlane refuses to arm with a
 *     landing under three quarters of its stopping distance after a waypoint ("VTOL land too short":
 *     AP_Arming_Plane::mission_checks), and a shorter approach overshoots and climbs back.</li>
 * </ul>
 */
final class VtolItems {

    static final String AIRSPEED_CRUISE = "AIRSPEED_CRUISE";
    static final String TECS_LAND_ARSPD = "TECS_LAND_ARSPD";
    static final String Q_TRANS_DECEL = "Q_TRANS_DECEL";
    static final String Q_OPTIONS = "Q_OPTIONS";
    static final String WP_RADIUS = "WP_RADIUS";
    static final List<String> PARAMETERS = List.of(AIRSPEED_CRUISE, TECS_LAND_ARSPD, Q_TRANS_DECEL, Q_OPTIONS, WP_RADIUS);

    private static final int ALLOW_FW_TAKEOFF = 1 << 1;
    private static final int ALLOW_FW_LAND = 1 << 2;
    /** A landing nearer its waypoint than this is over it: the approach comes from the navigation item before. */
    private static final double SAME_PLACE_METRES = 1;

    private final Boarding boarding;

    VtolItems(Boarding boarding) {
        this.boarding = boarding;
    }

    Boarded onBoard(List<MissionItem> items) {
        MissionItem home = items.get(0);
        List<MissionItem> out = new ArrayList<>();
        List<Integer> added = new ArrayList<>();
        for (MissionItem item : items) {
            FlightWay way = boarding.way(item.seq());
            MissionItem flown = switch (item.command()) {
                case MAV_CMD.MAV_CMD_NAV_TAKEOFF -> way == FlightWay.RUNWAY ? allowed(item, ALLOW_FW_TAKEOFF, "take-offs")
                        : vtolTakeoff(item, home);
                case MAV_CMD.MAV_CMD_NAV_LAND -> way == FlightWay.RUNWAY ? allowed(item, ALLOW_FW_LAND, "landings")
                        : vtolLand(item);
                // one read from a file: ArduPlane climbs its height whatever its frame, so a height above sea level goes above home
                case MAV_CMD.MAV_CMD_NAV_VTOL_TAKEOFF -> vtolTakeoff(item, home);
                default -> item;
            };
            if (landing(flown.command())) {
                for (MissionItem a : approach(out, flown)) {
                    added.add(out.size());
                    out.add(a.withSeq(out.size()));
                }
            }
            out.add(flown.withSeq(out.size()));
        }
        return new Boarded(out, added);
    }

    private static boolean landing(int command) {
        return command == MAV_CMD.MAV_CMD_NAV_LAND || command == MAV_CMD.MAV_CMD_NAV_VTOL_LAND;
    }

    /** A climb to the take-off's height above home (or above the ground, in a terrain frame), where the vehicle stands. */
    private static MissionItem vtolTakeoff(MissionItem t, MissionItem home) {
        boolean aboveSeaLevel = MissionItem.altitudeReference(t.frame()) == MAV_FRAME.MAV_FRAME_GLOBAL;
        float climb = aboveSeaLevel ? t.z() - home.z() : t.z();
        return new MissionItem(t.seq(), MAV_CMD.MAV_CMD_NAV_VTOL_TAKEOFF, MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT, 0, 0, 0,
                t.param4(), t.x(), t.y(), climb, t.autocontinue());
    }

    /** param1 0: the default approach, from where the vehicle comes (NAV_VTOL_LAND_OPTIONS_DEFAULT). */
    private static MissionItem vtolLand(MissionItem l) {
        return new MissionItem(l.seq(), MAV_CMD.MAV_CMD_NAV_VTOL_LAND, l.frame(), 0, 0, Float.NaN, l.param4(), l.x(), l.y(),
                l.z(), l.autocontinue());
    }

    private MissionItem allowed(MissionItem item, int bit, String what) {
        long options = (long) boarding.parameter(Q_OPTIONS).orElseThrow(() -> missing(Q_OPTIONS));
        if ((options & bit) == 0) {
            throw new IllegalArgumentException("item " + item.seq() + " (" + item.commandName() + ") is to be flown on a runway,"
                    + " but the vehicle flies it vertically: its Q_OPTIONS (" + options + ") do not allow fixed-wing " + what
                    + " (bit " + Integer.numberOfTrailingZeros(bit) + ")");
        }
        return item;
    }

    /**
     * The approach a landing needs when the navigation item before it is a waypoint nearer than the
     * stopping distance plus WP_RADIUS: ArduPlane counts a waypoint reached up to WP_RADIUS before it (at most),
     * so it may start its landing that much nearer, and heading away. The approach is a leg straight
     * to the landing: its far waypoint three WP_RADIUS beyond the near one, so that the vehicle turns
     * towards the near one before it reaches it; the near one the stopping distance out. Both are on
     * the side the vehicle comes from, at the waypoint's height. A DO item between the waypoint and
     * the landing does not give the vehicle more room (ArduPlane's check looks only at a waypoint
     * stored right before the landing; on SITL such a landing overshot and climbed back).
     */
    private List<MissionItem> approach(List<MissionItem> before, MissionItem landing) {
        int lastNav = MissionEnd.lastNavigation(before);
        MissionItem last = before.get(lastNav);
        if (lastNav == 0 || last.command() != MAV_CMD.MAV_CMD_NAV_WAYPOINT) {
            return List.of();
        }
        double stopping = stoppingDistance();
        double radius = boarding.parameter(WP_RADIUS).orElseThrow(() -> missing(WP_RADIUS));
        Position land = landing.position();
        if (land.horizontalDistanceTo(last.position()) >= stopping + radius) {
            return List.of();
        }
        double[] from = direction(before, land);
        return List.of(approachPoint(last, land, from, stopping + 3 * radius), approachPoint(last, land, from, stopping));
    }

    private static MissionItem approachPoint(MissionItem last, Position land, double[] from, double distance) {
        Position at = land.displace(from[0] * distance, from[1] * distance, 0);
        return new MissionItem(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, last.frame(), 0, last.param2(), last.param3(), last.param4(),
                MissionItem.degE7(at.latitudeDegrees()), MissionItem.degE7(at.longitudeDegrees()), last.z(), true);
    }

    /**
     * The unit (north, east) vector from the landing towards where the vehicle comes from: the last
     * navigation item not over the landing point; north when there is none.
     */
    private static double[] direction(List<MissionItem> before, Position land) {
        for (int i = before.size() - 1; i > 0; i--) {
            MissionItem item = before.get(i);
            if (item.command() < MAV_CMD.MAV_CMD_NAV_LAST && item.x() != 0) {
                double[] ned = land.displacementTo(item.position().atHeight(land.hae()));
                double length = Math.hypot(ned[0], ned[1]);
                if (length >= SAME_PLACE_METRES) {
                    return new double[] {ned[0] / length, ned[1] / length};
                }
            }
        }
        return new double[] {1, 0};
    }

    /** v²/(2·Q_TRANS_DECEL), v the landing airspeed (TECS_LAND_ARSPD when set, else AIRSPEED_CRUISE): QuadPlane::stopping_distance_m. */
    double stoppingDistance() {
        double landing = boarding.parameter(TECS_LAND_ARSPD).orElse(-1);
        double v = landing > 0 ? landing : boarding.parameter(AIRSPEED_CRUISE).orElseThrow(() -> missing(AIRSPEED_CRUISE));
        double decel = boarding.parameter(Q_TRANS_DECEL).orElseThrow(() -> missing(Q_TRANS_DECEL));
        return v * v / (2 * decel);
    }

    private static IllegalArgumentException missing(String parameter) {
        return new IllegalArgumentException(String.format(Locale.ROOT, "the vehicle did not give its %s parameter, which its"
                + " take-offs and landings are planned with%s", parameter,
                parameter.equals(AIRSPEED_CRUISE) ? " (ArduPlane before 4.5 named it TRIM_ARSPD_CM, which is not read)" : ""));
    }
}
