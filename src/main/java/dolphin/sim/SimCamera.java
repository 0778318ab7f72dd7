package dolphin.sim;

import com.MAVLink.common.msg_camera_information;
import com.MAVLink.enums.CAMERA_CAP_FLAGS;
import java.nio.charset.StandardCharsets;

/**
 * The CAMERA_INFORMATION a simulated vehicle with a camera sends when asked (MAV_CMD_REQUEST_MESSAGE),
 * from its autopilot as AP_Camera::send_camera_information does: a camera that takes pictures, with
 * no camera definition file.
 */
final class SimCamera {

    static final String VENDOR = "Dolphin";
    static final String MODEL = "SimCam";

    private SimCamera() {
    }

    static msg_camera_information information(long timeBootMillis) {
        msg_camera_information c = new msg_camera_information();
        c.time_boot_ms = timeBootMillis;
        c.vendor_name = padded(VENDOR, c.vendor_name.length);
        c.model_name = padded(MODEL, c.model_name.length);
        c.flags = CAMERA_CAP_FLAGS.CAMERA_CAP_FLAGS_CAPTURE_IMAGE;
        c.setCam_Definition_Uri("");
        return c;
    }

    /** uint8_t[n], NUL-padded: the generated class has no string setter for these. */
    private static short[] padded(String text, int n) {
        short[] out = new short[n];
        byte[] bytes = text.getBytes(StandardCharsets.US_ASCII);
        for (int i = 0; i < bytes.length; i++) {
            out[i] = bytes[i];
        }
        return out;
    }
}
