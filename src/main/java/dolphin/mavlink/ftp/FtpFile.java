package dolphin.mavlink.ftp;

/**
 * A file read from or written to the vehicle, with the requests sent again on the way.
 *
 * @param bytes the file's contents (those read, or those written)
 */
public record FtpFile(String path, byte[] bytes, int resends) {
}
