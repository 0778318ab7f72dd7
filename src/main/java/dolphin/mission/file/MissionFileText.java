package dolphin.mission.file;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CoderResult;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.function.Function;

/**
 * The text of a mission file, and errors that name it (docs/mission-files.md, "Formats"): UTF-8,
 * with or without the byte-order mark Windows editors write; a file in another encoding is refused
 * with the offset of its first byte that is not UTF-8, rather than read with replacement characters.
 */
final class MissionFileText {

    private static final char BOM = '\uFEFF';

    private MissionFileText() {
    }

    /** The file's text without a leading byte-order mark. */
    static String read(Path file) throws IOException {
        byte[] bytes = Files.readAllBytes(file);
        CharsetDecoder decoder = StandardCharsets.UTF_8.newDecoder()
                .onMalformedInput(CodingErrorAction.REPORT).onUnmappableCharacter(CodingErrorAction.REPORT);
        ByteBuffer in = ByteBuffer.wrap(bytes);
        CharBuffer out = CharBuffer.allocate(bytes.length);
        CoderResult result = decoder.decode(in, out, true);
        if (result.isError()) {
            throw new IllegalArgumentException(String.format(Locale.ROOT,
                    "%s: not UTF-8 text: byte 0x%02X at offset %d; save the file as UTF-8", file, bytes[in.position()] & 0xFF,
                    in.position()));
        }
        decoder.flush(out);
        return withoutBom(out.flip().toString());
    }

    static String withoutBom(String text) {
        return !text.isEmpty() && text.charAt(0) == BOM ? text.substring(1) : text;
    }

    /** Reads the file with {@code parse}; its errors are prefixed with the file's name. */
    static <T> T parse(Path file, Function<String, T> parse) throws IOException {
        String text = read(file);
        try {
            return parse.apply(text);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(file + ": " + e.getMessage(), e);
        }
    }
}
