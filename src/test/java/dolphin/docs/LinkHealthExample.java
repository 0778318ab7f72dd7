package dolphin.docs;

import dolphin.mavlink.LinkHealth;
import dolphin.platform.MAVLinkPlatform;
import java.util.Locale;

/** How a GUI shows a vehicle's link in its status bar. */
public final class LinkHealthExample {

    private LinkHealthExample() {
    }

    /** "serial:/dev/ttyUSB0:57600: 1.2/3.4 kB/s radio -62/-65 dBm txbuf 97%", or "" for an unknown vehicle. */
    public static String statusBar(MAVLinkPlatform platform, String vehicleId) {
        return platform.linkHealth(vehicleId).map(LinkHealthExample::describe).orElse("");
    }

    static String describe(LinkHealth h) {
        String rates = String.format(Locale.ROOT, "%.1f/%.1f kB/s", h.inBytesPerSecond() / 1000, h.outBytesPerSecond() / 1000);
        String radio = h.radioCurrent()
                ? String.format(Locale.ROOT, " radio %.0f/%.0f dBm txbuf %d%%", h.radio().rssiDbm(), h.radio().remrssiDbm(),
                        h.radio().txbuf())
                : "";
        return h.link() + ": " + rates + radio;
    }
}
