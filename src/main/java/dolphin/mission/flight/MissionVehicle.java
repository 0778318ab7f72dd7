package dolphin.mission.flight;

import dolphin.core.VehicleEvent.EventKind;
import dolphin.mavlink.CommandResult;
import dolphin.mavlink.VehicleState;
import dolphin.mission.model.MissionItem;
import dolphin.mission.model.MissionType;
import dolphin.mission.transfer.TransferResult;
import dolphin.mission.transfer.VehicleChannel;
import dolphin.mission.transfer.TransferStatus;
import java.util.List;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.concurrent.CompletableFuture;

/**
 * What a {@link MissionExecutor} needs of the vehicle it flies: beside the channel its messages go
 * on, its state, commands and transfers, and a way to wake the script when one of them completes.
 * {@link VehicleMissions} is the real one (a MAVLink node); executor specs pass a fake on a manual clock.
 */
public interface MissionVehicle extends VehicleChannel {

    /** The latest snapshot of its telemetry. */
    VehicleState state();

    /** Sends a COMMAND_LONG; completes with its COMMAND_ACK, or NO_ACK after the last attempt. */
    CompletableFuture<CommandResult> command(int command, float... params);

    /** Reads a parameter by name; completes empty when the vehicle did not answer (it has no such parameter). */
    CompletableFuture<OptionalDouble> parameter(String name);

    CompletableFuture<TransferResult> upload(MissionType type, List<MissionItem> items);

    CompletableFuture<TransferResult> download(MissionType type);

    /** Where the transfer in progress stands (items or bytes, resends); empty when none is. */
    Optional<TransferStatus> transfer();

    /** How missions are flown (deadlines, verification). */
    MissionExecutorConfig executorConfig();

    /** Steps the script's task tree at once, as telemetry does. */
    void wake();

    /** From now on the executor hears the vehicle's MISSION_ITEM_REACHED. */
    void flying(MissionExecutor executor);

    /** The executor has ended; a newer one that took the vehicle stays. */
    void landed(MissionExecutor executor);

    /**
     * Something a person watching the fleet should hear of (a pilot took the vehicle or handed it back, it
     * makes no progress), as a vehicle event; {@code text} does not name the vehicle.
     */
    void event(EventKind kind, String text);
}
