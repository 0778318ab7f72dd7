package dolphin.core;

/** Base executor for platform tasks: knows its vehicles and fails the task when one is lost. */
public abstract class PlatformTaskExecutor extends TaskExecutor {

    protected PlatformTaskExecutor(PlatformTask task) {
        super(task);
    }

    /** The first (usually the only) vehicle. */
    public Node getVehicle() {
        return getVehicles().get(0);
    }

    @Override
    protected CompletionState vehicleCheck() {
        for (Node v : getVehicles()) {
            if (!v.isConnected()) {
                return CompletionState.error("vehicle " + v.getId() + " lost: no contact within its connection timeout of "
                        + Math.round(v.getConnectionTimeout()) + " s");
            }
        }
        return null;
    }
}
