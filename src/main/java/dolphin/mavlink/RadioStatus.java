package dolphin.mavlink;

import com.MAVLink.ardupilotmega.msg_radio;
import com.MAVLink.common.msg_radio_status;
import java.time.Duration;

/**
 * A telemetry radio's report on its link (RADIO_STATUS, or RADIO from older firmware), as it was
 * sent: a SiK radio sends one to its own host, as system 51 component 68, for each heartbeat the
 * host sends. It tells of the radio, never of the vehicle behind it (docs/decisions.md, "Contact").
 *
 * @param rssi the local radio's received signal strength, in the radio's units (255: unknown)
 * @param remrssi the remote radio's, as it last told the local one
 * @param noise the local noise floor, in the same units
 * @param remnoise the remote noise floor
 * @param rxerrors packets the radio received with errors
 * @param fixed packets the radio's error correction repaired
 * @param txbuf percent of the local radio's transmit buffer that is free (a SiK radio's holds 1850
 *              bytes of serial data waiting for the air): a sender slows down as it falls
 * @param heardNanos the clock time the report came ({@link dolphin.core.Clock#nanoTime()})
 */
public record RadioStatus(int rssi, int remrssi, int noise, int remnoise, int rxerrors, int fixed, int txbuf, long heardNanos) {

    /** What RADIO_STATUS sends for a value the radio does not know (UINT8_MAX). */
    public static final int UNKNOWN = 255;

    static RadioStatus of(msg_radio_status m, long heardNanos) {
        return new RadioStatus(m.rssi, m.remrssi, m.noise, m.remnoise, m.rxerrors, m.fixed, m.txbuf, heardNanos);
    }

    static RadioStatus of(msg_radio m, long heardNanos) {
        return new RadioStatus(m.rssi, m.remrssi, m.noise, m.remnoise, m.rxerrors, m.fixed, m.txbuf, heardNanos);
    }

    /** The local signal in dBm on SiK's scale (raw / 1.9 - 127, as SiK's documentation gives it); NaN when unknown. */
    public double rssiDbm() {
        return dbm(rssi);
    }

    /** The remote signal in dBm on SiK's scale; NaN when unknown. */
    public double remrssiDbm() {
        return dbm(remrssi);
    }

    /** The local noise floor in dBm, on the same scale; NaN when unknown. */
    public double noiseDbm() {
        return dbm(noise);
    }

    /** The remote noise floor in dBm; NaN when unknown. */
    public double remnoiseDbm() {
        return dbm(remnoise);
    }

    /** How long ago the report came, at clock time {@code nowNanos}. */
    public Duration age(long nowNanos) {
        return Duration.ofNanos(Math.max(0, nowNanos - heardNanos));
    }

    private static double dbm(int raw) {
        return raw == UNKNOWN ? Double.NaN : raw / 1.9 - 127;
    }
}
