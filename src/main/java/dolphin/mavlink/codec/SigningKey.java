package dolphin.mavlink.codec;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;

/**
 * A MAVLink 2 signing secret (32 bytes). Signatures are the first 6 bytes of
 * SHA-256(secret + frame up to and including link id and timestamp).
 */
public final class SigningKey {

    private final byte[] secret;

    public SigningKey(byte[] secret) {
        if (secret.length != 32) {
            throw new IllegalArgumentException("a MAVLink signing key has 32 bytes, got " + secret.length);
        }
        this.secret = secret.clone();
    }

    /** The key as MAVProxy and QGroundControl derive it from a passphrase: SHA-256 of its UTF-8 bytes. */
    public static SigningKey fromPassphrase(String passphrase) {
        return new SigningKey(sha256().digest(passphrase.getBytes(StandardCharsets.UTF_8)));
    }

    /** 64 hex digits. */
    public static SigningKey fromHex(String hex) {
        return new SigningKey(HexFormat.of().parseHex(hex.strip()));
    }

    /** A file holding 64 hex digits, or a passphrase on its first line. */
    public static SigningKey fromFile(Path file) throws IOException {
        String text = Files.readString(file, StandardCharsets.UTF_8).lines().findFirst().orElse("").strip();
        return text.matches("[0-9a-fA-F]{64}") ? fromHex(text) : fromPassphrase(text);
    }

    /** The 6-byte signature of {@code frame[0, len)}, which must end with link id and timestamp. */
    byte[] sign(byte[] frame, int off, int len) {
        MessageDigest d = sha256();
        d.update(secret);
        d.update(frame, off, len);
        byte[] full = d.digest();
        return java.util.Arrays.copyOf(full, 6);
    }

    boolean verify(byte[] frame, int off, int frameLen) {
        byte[] expected = sign(frame, off, frameLen - 6);
        return MessageDigest.isEqual(expected, java.util.Arrays.copyOfRange(frame, off + frameLen - 6, off + frameLen));
    }

    private static MessageDigest sha256() {
        try {
            return MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }
}
