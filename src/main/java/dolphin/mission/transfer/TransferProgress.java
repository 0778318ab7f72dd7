package dolphin.mission.transfer;

/** Progress of a mission transfer, called on the communications thread: {@code done} of {@code total} items. */
@FunctionalInterface
public interface TransferProgress {

    TransferProgress NONE = (done, total) -> { };

    void progress(int done, int total);
}
