package dolphin.mission.transfer;

/** Progress of a mission transfer, called on the communications thread. */
@FunctionalInterface
public interface TransferProgress {

    TransferProgress NONE = status -> { };

    void progress(TransferStatus status);
}
