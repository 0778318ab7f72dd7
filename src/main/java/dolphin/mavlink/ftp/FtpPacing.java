package dolphin.mavlink.ftp;

import java.time.Duration;

/**
 * How an FTP transfer loads its link: the file bytes per request or reply, the requests outstanding
 * at most, and the shortest retransmission timeout (docs/radios.md, "Whole-list transfers").
 *
 * @param dataBytes the file bytes per request or reply, 1 to 239
 * @param window the requests outstanding at most while the link's radio, if any, has room
 * @param shortestTimeout no request is sent again sooner, whatever the measured round trip says
 * @param linkWindow the requests outstanding at most on the whole link, the transfers of all its
 *                   vehicles together (each transfer may always have one)
 */
public record FtpPacing(int dataBytes, int window, Duration shortestTimeout, int linkWindow) {

    /**
     * A network link: the protocol's 239 bytes, four requests (ArduPilot queues five requests, and a
     * network delivers a window at once), the transfer's own shortest timeout.
     */
    public static final FtpPacing NETWORK = new FtpPacing(FtpPayload.DATA_BYTES, 4, Duration.ZERO, Integer.MAX_VALUE);

    /**
     * A SiK telemetry radio. Its deployed firmware counts the bytes left in its time slot in 8 bits,
     * so a frame waits for a slot whose count happens to be larger: the smaller the frame, the
     * sooner. 96 bytes make a 123-byte frame, two to an air packet of 252. A serial port at 57600
     * baud delivers a frame every 20 ms or so, which ArduPilot's FTP thread (polling every 2 ms)
     * takes long before its queue of five fills, so eight may be outstanding. Its round trips swing
     * from 0.15 s to 0.8 s as slots and held frames come and go: resends wait at least 0.5 s. The
     * eight are for the whole radio: vehicles sharing one (multipoint) share its 1850-byte buffer.
     */
    public static final FtpPacing RADIO = new FtpPacing(96, 8, Duration.ofMillis(500), 8);

    public FtpPacing {
        if (dataBytes < 1 || dataBytes > FtpPayload.DATA_BYTES) {
            throw new IllegalArgumentException("FTP data bytes must be 1 to " + FtpPayload.DATA_BYTES + ", got " + dataBytes);
        }
        if (window < 1 || linkWindow < 1) {
            throw new IllegalArgumentException("FTP windows must be at least 1, got " + window + " and " + linkWindow);
        }
    }
}
