package dolphin.mavlink.codec;

import com.MAVLink.MAVLinkPacket;
import com.MAVLink.Messages.MAVLinkMessage;
import java.util.Arrays;

/**
 * One MAVLink frame as it was on the wire. The payload is as received (MAVLink 2 may truncate
 * trailing zeros); {@link #raw()} is the whole frame, for logs and forwarding.
 *
 * @param version 1 or 2
 * @param verified false for a message id the dialect does not define (its CRC cannot be checked)
 * @param signature the 13 signature bytes of a signed frame, else null
 */
public record Frame(int version, int incompatFlags, int compatFlags, int seq, int sysid, int compid, int msgid,
                    byte[] payload, byte[] signature, boolean verified, byte[] raw) {

    public static final int INCOMPAT_SIGNED = 0x01;

    public boolean signed() {
        return signature != null;
    }

    /** The signature's link id (0 when unsigned). */
    public int linkId() {
        return signed() ? signature[0] & 0xFF : 0;
    }

    /** The signature's timestamp in 10 µs units since 2015-01-01 (0 when unsigned). */
    public long signatureTimestamp() {
        if (!signed()) {
            return 0;
        }
        long t = 0;
        for (int i = 6; i >= 1; i--) {
            t = (t << 8) | (signature[i] & 0xFF);
        }
        return t;
    }

    /** The decoded message, or null when the dialect does not define the id. */
    public MAVLinkMessage message() {
        if (!MessageTable.get().known(msgid)) {
            return null;
        }
        // Unpacked as MAVLink 2 whatever the version: a MAVLink 1 frame that carries extension fields
        // (pymavlink sends them) is read the way pymavlink and the C library read it; absent ones are zero.
        MAVLinkPacket packet = new MAVLinkPacket(payload.length, true);
        packet.seq = seq;
        packet.sysid = sysid;
        packet.compid = compid;
        packet.msgid = msgid;
        packet.incompatFlags = incompatFlags;
        packet.compatFlags = compatFlags;
        packet.payload.getData().put(payload); // as add() byte by byte, in one copy
        MAVLinkMessage m = packet.unpack();
        if (m != null) {
            m.isMavlink2 = version == 2;
        }
        return m;
    }

    public String name() {
        return MessageTable.get().name(msgid);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Frame f && Arrays.equals(f.raw, raw);
    }

    @Override
    public int hashCode() {
        return Arrays.hashCode(raw);
    }

    @Override
    public String toString() {
        return name() + " v" + version + " seq " + seq + " from " + sysid + "/" + compid + (signed() ? " signed" : "");
    }
}
