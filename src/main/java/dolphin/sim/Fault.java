package dolphin.sim;

/**
 * Something that goes wrong with a simulated vehicle from the time it is injected ({@link SimFault}):
 * a motor, the GPS, a pilot taking over, a wind it cannot beat, a reboot, the link. It runs on the
 * fleet's tick in clock time and acts on the vehicle through its {@link FaultHost}; its texts,
 * severities and times are {@link FaultTable}'s, what differs between families their {@link Failures}.
 */
interface Fault {

    /** It happens: what changes at once. */
    void begin(FaultHost vehicle);

    /** One tick, {@code dt} seconds of clock time on; false once it is over and acts no more. */
    boolean step(FaultHost vehicle, double dt);

    /** Whether it keeps the vehicle's own flight (its mission, RTL or LAND) from moving it now. */
    default boolean holdsFlight(FaultHost vehicle) {
        return false;
    }
}
