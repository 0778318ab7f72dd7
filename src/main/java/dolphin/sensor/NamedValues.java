package dolphin.sensor;

import com.MAVLink.Messages.MAVLinkMessage;
import com.MAVLink.common.msg_named_value_float;
import com.MAVLink.common.msg_named_value_int;
import java.util.Set;

/**
 * NAMED_VALUE_FLOAT and NAMED_VALUE_INT, as ArduPilot Lua scripts ({@code gcs:send_named_float}) and
 * companion computers send them: the reading's name is the message's, up to 10 characters.
 */
public final class NamedValues implements Sensor {

    /** NAMED_VALUE's name is a char[10], not terminated when all ten are used: its length in the bindings. */
    public static final int MAX_NAME = new msg_named_value_float().name.length;

    NamedValues() {
    }

    @Override
    public Set<Class<? extends MAVLinkMessage>> messages() {
        return Set.of(msg_named_value_float.class, msg_named_value_int.class);
    }

    @Override
    public void read(MAVLinkMessage message, ReadingSink out) {
        if (message instanceof msg_named_value_float m) {
            out.put(name(m.name), m.value);
        } else if (message instanceof msg_named_value_int m) {
            out.put(name(m.name), m.value);
        }
    }

    /** The name up to its first NUL; a name with bytes that are not printable ASCII is refused. */
    private static String name(byte[] bytes) {
        StringBuilder b = new StringBuilder(MAX_NAME);
        for (byte c : bytes) {
            if (c == 0) {
                break;
            }
            if (c < 0x20 || c > 0x7e) {
                throw new IllegalArgumentException("a NAMED_VALUE name with byte 0x" + Integer.toHexString(c & 0xff)
                        + " after '" + b + "' (names are printable ASCII)");
            }
            b.append((char) c);
        }
        if (b.isEmpty()) {
            throw new IllegalArgumentException("a NAMED_VALUE with an empty name");
        }
        return b.toString();
    }
}
