package dolphin.mavlink.codec;

/**
 * The MAVLink checksum: CRC-16/MCRF4XX (X.25), seeded 0xFFFF. Runs of bytes are checksummed eight
 * at a time with lookup tables (slicing-by-8), which gives the same value as the byte-at-a-time
 * definition in {@link #accumulate(int, int)}.
 */
final class X25 {

    static final int SEED = 0xFFFF;

    /**
     * TABLE[k * 256 + i]: the checksum register after byte i followed by k zero bytes, from a zero
     * register. TABLE[0 .. 255] is the usual byte table.
     */
    private static final char[] TABLE = new char[8 * 256];

    static {
        for (int i = 0; i < 256; i++) {
            TABLE[i] = (char) accumulate(0, i);
        }
        for (int k = 1; k < 8; k++) {
            for (int i = 0; i < 256; i++) {
                int prev = TABLE[(k - 1) * 256 + i];
                TABLE[k * 256 + i] = (char) ((prev >>> 8) ^ TABLE[prev & 0xFF]);
            }
        }
    }

    private X25() {
    }

    static int accumulate(int crc, int b) {
        int tmp = (b ^ crc) & 0xFF;
        tmp = (tmp ^ (tmp << 4)) & 0xFF;
        return ((crc >>> 8) ^ (tmp << 8) ^ (tmp << 3) ^ (tmp >>> 4)) & 0xFFFF;
    }

    static int accumulate(int crc, byte[] buf, int off, int len) {
        if (len <= 0) {
            return crc;
        }
        char[] t = TABLE;
        int c = crc & 0xFFFF;
        int i = off;
        int end = off + len;
        // Eight bytes at a time: the register only overlaps the first two; each byte's contribution
        // is its table entry for the number of bytes that follow it in the block.
        for (; i <= end - 8; i += 8) {
            c = t[7 * 256 + ((c ^ buf[i]) & 0xFF)]
                    ^ t[6 * 256 + (((c >>> 8) ^ buf[i + 1]) & 0xFF)]
                    ^ t[5 * 256 + (buf[i + 2] & 0xFF)]
                    ^ t[4 * 256 + (buf[i + 3] & 0xFF)]
                    ^ t[3 * 256 + (buf[i + 4] & 0xFF)]
                    ^ t[2 * 256 + (buf[i + 5] & 0xFF)]
                    ^ t[256 + (buf[i + 6] & 0xFF)]
                    ^ t[buf[i + 7] & 0xFF];
        }
        // The rest (0 to 7 bytes) as at most one block of four, one of two and a single byte.
        if (end - i >= 4) {
            c = t[3 * 256 + ((c ^ buf[i]) & 0xFF)]
                    ^ t[2 * 256 + (((c >>> 8) ^ buf[i + 1]) & 0xFF)]
                    ^ t[256 + (buf[i + 2] & 0xFF)]
                    ^ t[buf[i + 3] & 0xFF];
            i += 4;
        }
        if (end - i >= 2) {
            c = t[256 + ((c ^ buf[i]) & 0xFF)] ^ t[((c >>> 8) ^ buf[i + 1]) & 0xFF];
            i += 2;
        }
        if (i < end) {
            c = (c >>> 8) ^ t[(c ^ buf[i]) & 0xFF];
        }
        return c;
    }
}
