package dolphin.core;

/** Decides what a {@link WatcherTask} does with its task's ERROR. */
@FunctionalInterface
public interface ErrorHandler {

    enum Decision { IGNORE, PROPAGATE }

    Decision handle(String message);
}
