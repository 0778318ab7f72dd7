package dolphin.mavlink;

import com.MAVLink.enums.MAV_CMD;
import com.MAVLink.enums.MAV_RESULT;

/**
 * The outcome of a COMMAND_LONG: the vehicle's MAV_RESULT, or {@link #NO_ACK} when no COMMAND_ACK
 * came after every retry.
 */
public record CommandResult(int command, int result, int attempts) {

    public static final int NO_ACK = -1;

    public boolean accepted() {
        return result == MAV_RESULT.MAV_RESULT_ACCEPTED;
    }

    public String commandName() {
        return EnumNames.name(MAV_CMD.class, "MAV_CMD_", command);
    }

    public String resultName() {
        return result == NO_ACK ? "no COMMAND_ACK" : EnumNames.name(MAV_RESULT.class, "MAV_RESULT_", result);
    }

    @Override
    public String toString() {
        return commandName() + ": " + resultName() + " after " + attempts + " attempt(s)";
    }
}
