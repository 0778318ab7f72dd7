package dolphin.sim;

/**
 * A vehicle without the thrust to fly: it comes down, its own way, and what follows on the ground is
 * the subclass's. Meanwhile no mode flies it: not its mission, not RTL or LAND.
 */
abstract class PowerLoss implements Fault {

    @Override
    public void begin(FaultHost vehicle) {
        // the thrust is gone; the descent follows tick by tick
    }

    @Override
    public final boolean step(FaultHost vehicle, double dt) {
        Craft craft = vehicle.craft();
        if (!craft.contact()) {
            descend(craft, dt);
            return true;
        }
        return grounded(vehicle, dt);
    }

    /** One step of its way down, for a craft not yet on the ground. */
    abstract void descend(Craft craft, double dt);

    /** One tick on the ground; false once the fault is over. */
    abstract boolean grounded(FaultHost vehicle, double dt);

    @Override
    public boolean holdsFlight(FaultHost vehicle) {
        return true;
    }
}
