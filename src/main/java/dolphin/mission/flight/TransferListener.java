package dolphin.mission.flight;

import dolphin.mission.transfer.TransferResult;
import dolphin.mission.transfer.TransferStatus;

/**
 * Hears the mission, fence and rally transfers the runtime makes (docs/embedding.md, "Mission
 * transfers"): their progress as it comes and how each ended. Called on the communications thread:
 * return quickly and hand work to your own thread.
 */
public interface TransferListener {

    /** A transfer to or from the vehicle advanced (items or bytes, resends). */
    void progress(String vehicleId, TransferStatus status);

    /** A transfer ended: its result says how. */
    default void ended(String vehicleId, TransferResult result) {
    }
}
