package dolphin.mavlink;

import java.util.PriorityQueue;

/** Deadlines in clock time for the communications thread; not thread-safe. */
final class Timers {

    private record Timer(long at, long order, Runnable action) {
    }

    private final PriorityQueue<Timer> queue = new PriorityQueue<>(
            (a, b) -> a.at != b.at ? Long.compare(a.at, b.at) : Long.compare(a.order, b.order));
    private long order;

    void at(long clockNanos, Runnable action) {
        queue.add(new Timer(clockNanos, order++, action));
    }

    /** Clock nanos of the next deadline, or Long.MAX_VALUE. */
    long next() {
        Timer t = queue.peek();
        return t == null ? Long.MAX_VALUE : t.at;
    }

    void runDue(long now) {
        while (!queue.isEmpty() && queue.peek().at <= now) {
            queue.poll().action.run();
        }
    }
}
