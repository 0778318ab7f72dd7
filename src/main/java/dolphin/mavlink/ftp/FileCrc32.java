package dolphin.mavlink.ftp;

/**
 * The CRC32 MAVLink FTP's CalcFileCRC32 answers with, as ArduPilot computes it (AP_Math's
 * crc_crc32 over the file from a start value of 0): the reflected polynomial 0xEDB88320 of zlib's
 * CRC32, without zlib's initial and final inversion.
 */
public final class FileCrc32 {

    private static final int[] TABLE = new int[256];

    static {
        for (int n = 0; n < 256; n++) {
            int c = n;
            for (int k = 0; k < 8; k++) {
                c = (c & 1) != 0 ? 0xEDB88320 ^ (c >>> 1) : c >>> 1;
            }
            TABLE[n] = c;
        }
    }

    private FileCrc32() {
    }

    /** The checksum of the whole of {@code bytes}, as an unsigned 32-bit value. */
    public static long of(byte[] bytes) {
        int crc = 0;
        for (byte b : bytes) {
            crc = TABLE[(crc ^ b) & 0xff] ^ (crc >>> 8);
        }
        return crc & 0xffffffffL;
    }
}
