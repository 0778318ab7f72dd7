package dolphin.core;

import java.time.Duration;
import java.util.PriorityQueue;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;

/**
 * Virtual time for tests. Time moves only when {@link #advance} is called or, in auto-advance
 * mode, when a thread sleeps: the clock then jumps to the sleeper's deadline at once, running the
 * scheduled events that fall on the way in time order. Auto-advance suits one sleeping thread (the
 * script thread); with several sleepers use explicit {@link #advance}.
 */
public final class ManualClock implements Clock {

    private record Event(long time, long order, Runnable action) {
    }

    private final ReentrantLock lock = new ReentrantLock();
    private final Condition changed = lock.newCondition();
    private final PriorityQueue<Event> events = new PriorityQueue<>(
            (a, b) -> a.time != b.time ? Long.compare(a.time, b.time) : Long.compare(a.order, b.order));
    private final boolean autoAdvance;
    private long now;
    private long order;

    /** A clock whose sleepers wait for {@link #advance}. */
    public ManualClock() {
        this(false);
    }

    public ManualClock(boolean autoAdvance) {
        this.autoAdvance = autoAdvance;
    }

    public static ManualClock autoAdvancing() {
        return new ManualClock(true);
    }

    @Override
    public long nanoTime() {
        lock.lock();
        try {
            return now;
        } finally {
            lock.unlock();
        }
    }

    /** Runs {@code action} on the advancing thread when the clock reaches now + delay. */
    public void schedule(Duration delay, Runnable action) {
        lock.lock();
        try {
            events.add(new Event(now + delay.toNanos(), order++, action));
        } finally {
            lock.unlock();
        }
    }

    /** Moves time forward, running due events in order and waking sleepers whose time has come. */
    public void advance(Duration duration) {
        advanceTo(nanoTime() + duration.toNanos(), null);
    }

    @Override
    public void sleep(Duration duration) throws InterruptedException {
        await(duration, new ManualWakeup());
    }

    /** Virtual time does not pass while a thread blocks on I/O, so such waits only poll (1 ms). */
    @Override
    public long realNanos(long clockNanos) {
        return Math.min(clockNanos, 1_000_000L);
    }

    @Override
    public Wakeup newWakeup() {
        return new ManualWakeup();
    }

    private void await(Duration timeout, ManualWakeup wakeup) throws InterruptedException {
        long deadline = nanoTime() + Math.max(0, timeout.toNanos());
        if (autoAdvance) {
            advanceTo(deadline, wakeup);
            if (Thread.interrupted()) {
                throw new InterruptedException();
            }
            return;
        }
        lock.lockInterruptibly();
        try {
            while (now < deadline && !wakeup.pending) {
                changed.await();
            }
        } finally {
            lock.unlock();
        }
    }

    /** Advances to {@code target}, stopping early (at an event's time) when {@code wakeup} is woken. */
    private void advanceTo(long target, ManualWakeup wakeup) {
        while (true) {
            Event next;
            lock.lock();
            try {
                if (wakeup != null && wakeup.pending) {
                    return;
                }
                next = events.peek();
                if (next == null || next.time > target) {
                    now = Math.max(now, target);
                    changed.signalAll();
                    return;
                }
                events.poll();
                now = Math.max(now, next.time);
                changed.signalAll();
            } finally {
                lock.unlock();
            }
            next.action.run();
        }
    }

    private final class ManualWakeup implements Wakeup {
        private boolean pending;

        @Override
        public void await(Duration timeout) throws InterruptedException {
            try {
                ManualClock.this.await(timeout, this);
            } finally {
                lock.lock();
                try {
                    pending = false;
                } finally {
                    lock.unlock();
                }
            }
        }

        @Override
        public void wake() {
            lock.lock();
            try {
                pending = true;
                changed.signalAll();
            } finally {
                lock.unlock();
            }
        }
    }
}
