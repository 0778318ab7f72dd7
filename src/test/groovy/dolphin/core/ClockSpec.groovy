package dolphin.core

import spock.lang.Specification
import spock.lang.Timeout
import spock.lang.Unroll

import java.time.Duration
import java.util.concurrent.TimeUnit

/**
 * ManualClock (virtual time for tests) and SystemClock (real time with a speed-up). Real-time
 * waits are bounded and only checked against generous limits.
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class ClockSpec extends Specification {

    static Duration secs(double s) { Duration.ofNanos(Math.round(s * 1e9)) }

    /** Spins (without sleeping) until the thread is parked in a wait, or fails after 10 s. */
    static void awaitParked(Thread t) {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10)
        while (!(t.state in [Thread.State.WAITING, Thread.State.TIMED_WAITING])) {
            assert t.alive: 'the thread ended instead of waiting'
            assert System.nanoTime() < deadline: 'the thread never started waiting'
            Thread.onSpinWait()
        }
    }

    // ---- ManualClock

    def "a manual clock starts at 0 and moves only when advanced"() {
        given:
        def clock = new ManualClock()

        expect:
        clock.nanoTime() == 0
        clock.seconds() == 0d

        when:
        clock.advance(Duration.ofMillis(1500))
        clock.advance(Duration.ofMillis(250))

        then:
        clock.nanoTime() == 1_750_000_000L
        clock.seconds() == 1.75d
    }

    def "scheduled events run in time order, at their own times, and only once their time is reached"() {
        given:
        def clock = new ManualClock()
        List<String> ran = []
        clock.schedule(secs(3), { ran << "c@${clock.seconds()}".toString() } as Runnable)
        clock.schedule(secs(1), { ran << "a@${clock.seconds()}".toString() } as Runnable)
        clock.schedule(secs(2), { ran << "b@${clock.seconds()}".toString() } as Runnable)

        when:
        clock.advance(secs(2.5))

        then:
        ran == ['a@1.0', 'b@2.0']
        clock.seconds() == 2.5d

        when:
        clock.advance(secs(1))

        then:
        ran == ['a@1.0', 'b@2.0', 'c@3.0']
    }

    def "events due at the same time run in the order they were scheduled"() {
        given:
        def clock = new ManualClock()
        List<Integer> ran = []
        (1..5).each { i -> clock.schedule(secs(1), { ran << i } as Runnable) }

        when:
        clock.advance(secs(1))

        then:
        ran == [1, 2, 3, 4, 5]
    }

    def "an event's delay counts from when it is scheduled, and an event may schedule the next"() {
        given:
        def clock = new ManualClock()
        List<Double> ran = []
        Runnable tick
        tick = { ran << clock.seconds(); if (ran.size() < 4) clock.schedule(secs(0.5), tick) } as Runnable
        clock.advance(secs(1))
        clock.schedule(secs(0.5), tick)

        when:
        clock.advance(secs(10))

        then:
        ran == [1.5d, 2.0d, 2.5d, 3.0d]
    }

    def "an auto-advancing clock jumps to a sleeper's deadline at once, running the events on the way"() {
        given:
        def clock = ManualClock.autoAdvancing()
        List<String> ran = []
        clock.schedule(secs(0.5), { ran << "a@${clock.seconds()}".toString() } as Runnable)
        clock.schedule(secs(1.5), { ran << "b@${clock.seconds()}".toString() } as Runnable)
        clock.schedule(secs(3), { ran << "c@${clock.seconds()}".toString() } as Runnable)
        long realStart = System.nanoTime()

        when:
        clock.sleep(secs(2))

        then:
        clock.seconds() == 2.0d
        ran == ['a@0.5', 'b@1.5']
        (System.nanoTime() - realStart) < TimeUnit.SECONDS.toNanos(2)

        when:
        clock.sleep(secs(2))

        then:
        clock.seconds() == 4.0d
        ran == ['a@0.5', 'b@1.5', 'c@3.0']
    }

    def "on a non-advancing clock a sleeper wakes when the clock reaches its deadline, not before"() {
        given:
        def clock = new ManualClock()
        double wokeAt = -1
        def sleeper = Thread.start { clock.sleep(secs(2)); wokeAt = clock.seconds() }
        awaitParked(sleeper)

        when:
        clock.advance(secs(1))
        clock.advance(secs(1))
        sleeper.join(10_000)

        then:
        !sleeper.alive
        wokeAt == 2.0d
    }

    def "a wakeup cuts a wait short at the time of the wake"() {
        given:
        def clock = ManualClock.autoAdvancing()
        def wakeup = clock.newWakeup()
        clock.schedule(secs(3), { wakeup.wake() } as Runnable)

        when:
        wakeup.await(secs(10))

        then:
        clock.seconds() == 3.0d
    }

    def "a wake before the wait ends the next wait at once; each wake is consumed by one wait"() {
        given:
        def clock = ManualClock.autoAdvancing()
        def wakeup = clock.newWakeup()

        when:
        wakeup.wake()
        wakeup.await(secs(10))

        then:
        clock.seconds() == 0d

        when:
        wakeup.await(secs(1))

        then:
        clock.seconds() == 1.0d
    }

    def "on a non-advancing clock a wake from another thread ends a wait without moving time"() {
        given:
        def clock = new ManualClock()
        def wakeup = clock.newWakeup()
        def waiter = Thread.start { wakeup.await(secs(60)) }
        awaitParked(waiter)

        when:
        wakeup.wake()
        waiter.join(10_000)

        then:
        !waiter.alive
        clock.seconds() == 0d
    }

    def "an interrupted sleeper on an auto-advancing clock gets an InterruptedException"() {
        given:
        def clock = ManualClock.autoAdvancing()

        when:
        Thread.currentThread().interrupt()
        clock.sleep(secs(1))

        then:
        thrown(InterruptedException)

        cleanup:
        Thread.interrupted()
    }

    // ---- SystemClock

    def "a system clock with a speed-up scales time and sleeps"() {
        given:
        def clock = new SystemClock(50)
        long realStart = System.nanoTime()
        long clockStart = clock.nanoTime()

        when:
        clock.sleep(Duration.ofSeconds(2))
        long clockElapsed = clock.nanoTime() - clockStart
        long realElapsed = System.nanoTime() - realStart

        then: 'two clock seconds pass, in about 40 ms of real time'
        clockElapsed >= 1_990_000_000L
        realElapsed < TimeUnit.MILLISECONDS.toNanos(1500)
        clockElapsed <= realElapsed * 50 + 1_000_000L
        clock.speedup() == 50d
    }

    def "the real system clock runs at real speed"() {
        given:
        def clock = SystemClock.REAL
        long realStart = System.nanoTime()
        long clockStart = clock.nanoTime()

        when:
        clock.sleep(Duration.ofMillis(20))
        long clockElapsed = clock.nanoTime() - clockStart
        long realElapsed = System.nanoTime() - realStart

        then:
        clock.speedup() == 1d
        clockElapsed >= TimeUnit.MILLISECONDS.toNanos(19)
        clockElapsed <= realElapsed + 1_000_000L
    }

    def "a system clock wakeup ends a long wait as soon as another thread wakes it"() {
        given:
        def clock = new SystemClock(1)
        def wakeup = clock.newWakeup()
        long realStart = System.nanoTime()
        def waiter = Thread.start { wakeup.await(Duration.ofSeconds(60)) }
        awaitParked(waiter)

        when:
        wakeup.wake()
        waiter.join(10_000)

        then:
        !waiter.alive
        (System.nanoTime() - realStart) < TimeUnit.SECONDS.toNanos(10)
    }

    def "a system clock wake before the wait ends it at once"() {
        given:
        def wakeup = new SystemClock(1).newWakeup()
        long realStart = System.nanoTime()

        when:
        wakeup.wake()
        wakeup.await(Duration.ofSeconds(60))

        then:
        (System.nanoTime() - realStart) < TimeUnit.SECONDS.toNanos(10)
    }

    @Unroll
    def "a speed-up of #speedup is rejected"() {
        when:
        new SystemClock(speedup)

        then:
        thrown(IllegalArgumentException)

        where:
        speedup << [0d, -1d, Double.NaN, Double.POSITIVE_INFINITY]
    }
}
