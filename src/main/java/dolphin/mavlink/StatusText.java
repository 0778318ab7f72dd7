package dolphin.mavlink;

import com.MAVLink.common.msg_statustext;

/** A STATUSTEXT's words as the vehicle means them. */
public final class StatusText {

    private StatusText() {
    }

    /** The text without the white space around it: PX4 ends each of its texts with a tab. */
    public static String of(msg_statustext message) {
        return message.getText().strip();
    }
}
