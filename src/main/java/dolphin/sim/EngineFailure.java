package dolphin.sim;

/**
 * A plane's engine stops: it glides on along its heading at its speed, sinking at its sink rate, in
 * whatever mode it is, until it hits the ground; {@link FaultTable#PLANE_LANDED_AFTER} seconds later
 * ArduPlane no longer thinks it flies (EXTENDED_SYS_STATE ON_GROUND). ArduPlane says nothing of it;
 * it stays armed, in its mode, at its mission item.
 */
final class EngineFailure implements Fault {

    private double stopped;

    @Override
    public void begin(FaultHost vehicle) {
        // the engine stops; the glide follows tick by tick
    }

    @Override
    public boolean step(FaultHost vehicle, double dt) {
        Craft craft = vehicle.craft();
        if (!craft.contact()) {
            craft.glide(craft.performance().sink(), dt);
        } else if (!craft.onGround()) {
            stopped += dt;
            if (stopped >= FaultTable.PLANE_LANDED_AFTER) {
                craft.settle();
            }
        }
        return true;
    }

    /** Without its engine it flies no more. */
    @Override
    public boolean holdsFlight(FaultHost vehicle) {
        return true;
    }
}
