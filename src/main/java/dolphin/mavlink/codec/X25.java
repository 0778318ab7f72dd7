package dolphin.mavlink.codec;

/** The MAVLink checksum: CRC-16/MCRF4XX (X.25), seeded 0xFFFF. */
final class X25 {

    static final int SEED = 0xFFFF;

    private X25() {
    }

    static int accumulate(int crc, int b) {
        int tmp = (b ^ crc) & 0xFF;
        tmp = (tmp ^ (tmp << 4)) & 0xFF;
        return ((crc >>> 8) ^ (tmp << 8) ^ (tmp << 3) ^ (tmp >>> 4)) & 0xFFFF;
    }

    static int accumulate(int crc, byte[] buf, int off, int len) {
        int c = crc;
        for (int i = off; i < off + len; i++) {
            c = accumulate(c, buf[i]);
        }
        return c;
    }
}
