package dolphin.mavlink;

import java.time.Duration;

/**
 * One link's health at one moment, immutable: what it carries each way, what it loses, and what
 * the telemetry radio on it last reported (docs/mavlink.md, "The ground station"; docs/decisions.md,
 * "Link health").
 *
 * @param link the link as it was given ("serial:/dev/ttyUSB0:57600", "udpin:0.0.0.0:14559")
 * @param inBytesPerSecond bytes received per second, over the last few seconds of clock time
 * @param outBytesPerSecond bytes sent per second, likewise
 * @param bytesIn every byte received since the link opened
 * @param bytesOut every byte sent
 * @param framesLost frames that never came, from the gaps in their senders' sequence numbers
 * @param badCrcs frames dropped for a bad checksum (line noise on a serial link)
 * @param framesDropped frames dropped for any reason, bad checksums included
 * @param radio the latest RADIO_STATUS (or RADIO) heard on the link from any system, null before one
 * @param radioAge how long ago it came, null with it
 */
public record LinkHealth(String link, double inBytesPerSecond, double outBytesPerSecond, long bytesIn, long bytesOut,
                         long framesLost, long badCrcs, long framesDropped, RadioStatus radio, Duration radioAge) {

    /** A radio report older than this is old news: a SiK radio reports once a second, on each of our heartbeats. */
    public static final Duration RADIO_CURRENT = Duration.ofSeconds(5);

    /** Nothing counted: a link the communications do not run (a node made by a test). */
    static LinkHealth unmeasured(String link) {
        return new LinkHealth(link, 0, 0, 0, 0, 0, 0, 0, null, null);
    }

    /** Whether a radio reports on the link, and its report is younger than {@link #RADIO_CURRENT}. */
    public boolean radioCurrent() {
        return radio != null && radioAge.compareTo(RADIO_CURRENT) < 0;
    }
}
