package dolphin.mavlink.codec;

import com.MAVLink.MAVLinkPacket;
import com.MAVLink.Messages.MAVLinkMessage;

/**
 * Writes MAVLink 2 frames for one sender (system and component) on one link: an incrementing
 * sequence number, trailing zeros of the payload truncated, and a signature when a key is set.
 * Not thread-safe; the communications thread owns it.
 */
public final class FrameWriter {

    /** 2015-01-01T00:00:00Z, the epoch of signature timestamps. */
    private static final long SIGNING_EPOCH_MILLIS = 1420070400000L;

    private final int sysid;
    private final int compid;
    private final SigningKey key;
    private final int linkId;
    private int seq;
    private long lastTimestamp;

    public FrameWriter(int sysid, int compid) {
        this(sysid, compid, null, 0);
    }

    public FrameWriter(int sysid, int compid, SigningKey key, int linkId) {
        this.sysid = sysid;
        this.compid = compid;
        this.key = key;
        this.linkId = linkId;
    }

    public int sysid() {
        return sysid;
    }

    public int compid() {
        return compid;
    }

    public byte[] write(MAVLinkMessage message) {
        // The generated pack() leaves the extension fields out unless the message is marked MAVLink 2
        // (new messages are not): this writer only writes MAVLink 2, so mark it.
        message.isMavlink2 = true;
        MAVLinkPacket packet = message.pack();
        byte[] data = packet.payload.getData().array();
        int len = packet.payload.size();
        while (len > 1 && data[len - 1] == 0) {
            len--;
        }
        boolean signed = key != null;
        byte[] frame = new byte[10 + len + 2 + (signed ? 13 : 0)];
        frame[0] = (byte) 0xFD;
        frame[1] = (byte) len;
        frame[2] = (byte) (signed ? Frame.INCOMPAT_SIGNED : 0);
        frame[3] = 0;
        frame[4] = (byte) seq;
        frame[5] = (byte) sysid;
        frame[6] = (byte) compid;
        int msgid = packet.msgid;
        frame[7] = (byte) msgid;
        frame[8] = (byte) (msgid >>> 8);
        frame[9] = (byte) (msgid >>> 16);
        System.arraycopy(data, 0, frame, 10, len);
        int crc = X25.accumulate(X25.SEED, frame, 1, 9 + len);
        int extra = MessageTable.get().crcExtra(msgid);
        if (extra < 0) {
            throw new IllegalArgumentException("message id " + msgid + " is not in the dialect");
        }
        crc = X25.accumulate(crc, extra);
        frame[10 + len] = (byte) crc;
        frame[11 + len] = (byte) (crc >>> 8);
        if (signed) {
            int at = 12 + len;
            frame[at] = (byte) linkId;
            long ts = nextTimestamp();
            for (int i = 0; i < 6; i++) {
                frame[at + 1 + i] = (byte) (ts >>> (8 * i));
            }
            byte[] sig = key.sign(frame, 0, at + 7);
            System.arraycopy(sig, 0, frame, at + 7, 6);
        }
        seq = (seq + 1) & 0xFF;
        return frame;
    }

    /** 10 µs units since 2015 from the wall clock, strictly increasing as the signing spec requires. */
    private long nextTimestamp() {
        long now = (System.currentTimeMillis() - SIGNING_EPOCH_MILLIS) * 100;
        lastTimestamp = Math.max(now, lastTimestamp + 1);
        return lastTimestamp;
    }
}
