package dolphin.mavlink.ftp;

import java.util.OptionalLong;

/**
 * A file written, and the CRC32 of what the vehicle holds once it closed it ({@link FileCrc32}):
 * empty when the vehicle refused to compute it or did not answer.
 */
public record CheckedFile(FtpFile file, OptionalLong vehicleCrc) {
}
