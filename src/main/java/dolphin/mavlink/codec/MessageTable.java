package dolphin.mavlink.codec;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;

/**
 * CRC_EXTRA and name of every message of the dialect, read from the table the
 * build generates from the pinned pymavlink (dolphin/mavlink/messages.tsv).
 */
public final class MessageTable {

    private static final int IDS = 1 << 24;
    private static final MessageTable INSTANCE = load();

    private final short[] crcExtra;
    private final String[] names;
    private final java.util.Map<String, Integer> ids = new java.util.HashMap<>();

    private MessageTable(int maxId) {
        crcExtra = new short[maxId + 1];
        names = new String[maxId + 1];
        java.util.Arrays.fill(crcExtra, (short) -1);
    }

    public static MessageTable get() {
        return INSTANCE;
    }

    /** The CRC_EXTRA byte of a message id, or -1 for an id the dialect does not define. */
    public int crcExtra(int msgid) {
        return msgid >= 0 && msgid < crcExtra.length ? crcExtra[msgid] : -1;
    }

    public boolean known(int msgid) {
        return crcExtra(msgid) >= 0;
    }

    /** The message name, or "#id" for an unknown id. */
    public String name(int msgid) {
        return known(msgid) ? names[msgid] : "#" + msgid;
    }

    /** The id of a message name ("VFR_HUD"), or -1 for a name the dialect does not define. */
    public int id(String name) {
        return ids.getOrDefault(name, -1);
    }

    /** Every message name of the dialect. */
    public java.util.Set<String> messageNames() {
        return java.util.Collections.unmodifiableSet(ids.keySet());
    }

    private static MessageTable load() {
        String resource = "/dolphin/mavlink/messages.tsv";
        try (InputStream in = MessageTable.class.getResourceAsStream(resource)) {
            if (in == null) {
                throw new IllegalStateException("missing " + resource + ": the build generates it (harness/generate-bindings.sh)");
            }
            var lines = new BufferedReader(new InputStreamReader(in, StandardCharsets.US_ASCII)).lines()
                    .filter(l -> !l.startsWith("#") && !l.isBlank()).map(l -> l.split("\t")).toList();
            int max = lines.stream().mapToInt(f -> Integer.parseInt(f[0])).max().orElse(0);
            if (max >= IDS) {
                throw new IllegalStateException("message id out of range in " + resource + ": " + max);
            }
            MessageTable t = new MessageTable(max);
            for (String[] f : lines) {
                int id = Integer.parseInt(f[0]);
                t.names[id] = f[1];
                t.ids.put(f[1], id);
                t.crcExtra[id] = Short.parseShort(f[2]);
            }
            return t;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
