package dolphin.sim;

/**
 * A plane's engine stops: it glides on along its heading at its speed, sinking at
 * {@link FaultTable#PLANE_GLIDE_SINK}, in whatever mode it is, until it hits the ground;
 * {@link FaultTable#PLANE_LANDED_AFTER} seconds later ArduPlane no longer thinks it flies
 * (EXTENDED_SYS_STATE ON_GROUND). ArduPlane says nothing of it; it stays armed, in its mode, at its
 * mission item.
 */
final class EngineFailure extends PowerLoss {

    private double stopped;

    @Override
    void descend(Craft craft, double dt) {
        craft.glide(FaultTable.PLANE_GLIDE_SINK, dt);
    }

    @Override
    boolean grounded(FaultHost vehicle, double dt) {
        stopped += dt;
        if (stopped >= FaultTable.PLANE_LANDED_AFTER) {
            vehicle.craft().settle();
        }
        return true;
    }
}
