package dolphin.testing

import dolphin.core.CompletionState
import dolphin.core.NodeFilter
import dolphin.core.PlatformTask
import dolphin.core.PlatformTaskExecutor

/**
 * A platform task for tests: "flies" for a given clock time and is DONE, or fails with a message
 * after {@code failAfter} seconds. Every start, end and stop is recorded in the platform's journal.
 */
class FlyTask extends PlatformTask {
    final TestPlatform platform
    final double seconds
    final Double failAfter
    final String failMessage
    final NodeFilter requirement

    FlyTask(TestPlatform platform, String id, double seconds, Double failAfter = null, String failMessage = null,
            NodeFilter requirement = NodeFilter.ANY) {
        super(id)
        this.platform = platform
        this.seconds = seconds
        this.failAfter = failAfter
        this.failMessage = failMessage
        this.requirement = requirement
    }

    @Override
    List<NodeFilter> getRequirements() { [requirement] }

    @Override
    PlatformTaskExecutor getExecutor() {
        new PlatformTaskExecutor(this) {
            @Override
            protected void onStart() { platform.record('start', id, vehicle.id, clock().seconds()) }

            @Override
            protected CompletionState onStep() {
                if (failAfter != null && timeElapsed() >= failAfter) {
                    return CompletionState.error(failMessage)
                }
                timeElapsed() >= seconds ? CompletionState.DONE : CompletionState.IN_PROGRESS
            }

            @Override
            protected void onCompletion() {
                platform.record(completionState.error ? 'error' : 'done', id, vehicle.id, clock().seconds())
            }

            @Override
            protected void onStop() { platform.record('stop', id, vehicle.id, clock().seconds()) }
        }
    }
}
