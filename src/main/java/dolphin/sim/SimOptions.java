package dolphin.sim;

/**
 * Behaviour knobs of simulated vehicles.
 *
 * @param warmupSeconds arming is refused ("PreArm: ...") until this long after boot (ArduCopter SITL: about 42 s)
 * @param drainPercentPerMinute battery use while armed (ArduCopter SITL: about 14 %/min)
 * @param messageIntervalSupported false makes MAV_CMD_SET_MESSAGE_INTERVAL UNSUPPORTED (older firmware)
 * @param refuseModeChanges true makes every mode change fail
 */
public record SimOptions(double warmupSeconds, double drainPercentPerMinute, boolean messageIntervalSupported,
                         boolean refuseModeChanges) {

    public static final SimOptions DEFAULT = new SimOptions(0, 14, true, false);

    public SimOptions withWarmup(double seconds) {
        return new SimOptions(seconds, drainPercentPerMinute, messageIntervalSupported, refuseModeChanges);
    }

    public SimOptions withDrain(double percentPerMinute) {
        return new SimOptions(warmupSeconds, percentPerMinute, messageIntervalSupported, refuseModeChanges);
    }

    public SimOptions withoutMessageInterval() {
        return new SimOptions(warmupSeconds, drainPercentPerMinute, false, refuseModeChanges);
    }
}
