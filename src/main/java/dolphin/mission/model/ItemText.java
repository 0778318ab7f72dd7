package dolphin.mission.model;

import com.MAVLink.enums.MAV_FRAME;
import java.math.BigDecimal;

/**
 * An item's numbers as text, as the files and the tables write them, and the frames files name.
 *
 * <p>Files carry latitude and longitude as floating degrees, like MISSION_ITEM, so they name the
 * float frames (MAV_FRAME_GLOBAL, GLOBAL_RELATIVE_ALT, GLOBAL_TERRAIN_ALT), as QGroundControl and
 * Mission Planner write them; our items use the _INT frames of MISSION_ITEM_INT. Writing maps
 * GLOBAL_INT to GLOBAL (and the other two likewise), reading maps them back; other frames pass
 * unchanged. x and y are degrees (degE7 / 10^7) in every frame, as ArduPilot reads MISSION_ITEM.
 */
public final class ItemText {

    private ItemText() {
    }

    /** The frame a file names for an item's frame. */
    public static int fileFrame(int frame) {
        return switch (frame) {
            case MAV_FRAME.MAV_FRAME_GLOBAL_INT -> MAV_FRAME.MAV_FRAME_GLOBAL;
            case MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT -> MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT;
            case MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT_INT -> MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT;
            default -> frame;
        };
    }

    /** The item frame for a frame read from a file. */
    public static int itemFrame(int fileFrame) {
        return switch (fileFrame) {
            case MAV_FRAME.MAV_FRAME_GLOBAL -> MAV_FRAME.MAV_FRAME_GLOBAL_INT;
            case MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT -> MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT;
            case MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT -> MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT_INT;
            default -> fileFrame;
        };
    }

    /** True for the frames whose x, y, z are a latitude, longitude and altitude. */
    public static boolean isGlobal(int frame) {
        return switch (itemFrame(frame)) {
            case MAV_FRAME.MAV_FRAME_GLOBAL_INT, MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT,
                    MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT_INT -> true;
            default -> false;
        };
    }

    /** degE7 as exact degrees with 7 decimals, e.g. 404442330 -> "40.4442330". */
    public static String degrees(int degE7) {
        return BigDecimal.valueOf(degE7, 7).toPlainString();
    }

    /**
     * A float as the shortest decimal that reads back to it, without an exponent; "nan", "inf" and
     * "-inf" as Python writes them (pymavlink reads them with float()); -0 keeps its sign.
     */
    public static String number(float f) {
        if (Float.isNaN(f)) {
            return "nan";
        }
        if (Float.isInfinite(f)) {
            return f > 0 ? "inf" : "-inf";
        }
        if (f == 0) {
            return Float.floatToRawIntBits(f) == 0 ? "0" : "-0";
        }
        return new BigDecimal(Float.toString(f)).stripTrailingZeros().toPlainString();
    }
}
