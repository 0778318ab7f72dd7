package dolphin.core;

import java.time.Duration;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;

/** The machine's monotonic clock, optionally running faster than real time by a speed-up factor. */
public final class SystemClock implements Clock {

    public static final SystemClock REAL = new SystemClock(1.0);

    private final double speedup;
    private final long origin = System.nanoTime();

    public SystemClock(double speedup) {
        if (!(speedup > 0) || Double.isInfinite(speedup)) {
            throw new IllegalArgumentException("speed-up must be a positive number, got " + speedup);
        }
        this.speedup = speedup;
    }

    public double speedup() {
        return speedup;
    }

    @Override
    public long nanoTime() {
        return (long) ((System.nanoTime() - origin) * speedup);
    }

    @Override
    public void sleep(Duration duration) throws InterruptedException {
        long real = toReal(duration);
        if (real > 0) {
            TimeUnit.NANOSECONDS.sleep(real);
        } else if (Thread.interrupted()) {
            throw new InterruptedException();
        }
    }

    @Override
    public long realNanos(long clockNanos) {
        return (long) (clockNanos / speedup);
    }

    @Override
    public Wakeup newWakeup() {
        return new Wakeup() {
            private final ReentrantLock lock = new ReentrantLock();
            private final Condition woken = lock.newCondition();
            private boolean pending;

            @Override
            public void await(Duration timeout) throws InterruptedException {
                long remaining = toReal(timeout);
                lock.lockInterruptibly();
                try {
                    while (!pending && remaining > 0) {
                        remaining = woken.awaitNanos(remaining);
                    }
                    pending = false;
                } finally {
                    lock.unlock();
                }
                if (Thread.interrupted()) {
                    throw new InterruptedException();
                }
            }

            @Override
            public void wake() {
                lock.lock();
                try {
                    pending = true;
                    woken.signalAll();
                } finally {
                    lock.unlock();
                }
            }
        };
    }

    private long toReal(Duration duration) {
        return realNanos(duration.toNanos());
    }
}
