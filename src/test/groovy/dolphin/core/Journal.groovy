package dolphin.core

import java.math.RoundingMode

/**
 * What happened to {@link Probe} tasks, in order: init (with the allocated vehicles), start, step,
 * done, error and stop, each with the clock time at which it happened.
 */
class Journal {

    static final class Entry {
        final String kind
        final String task
        final List<String> vehicles
        final double time

        Entry(String kind, String task, List<String> vehicles, double time) {
            this.kind = kind
            this.task = task
            this.vehicles = vehicles
            this.time = time
        }

        String toString() { "${kind} ${task}${vehicles ? ' ' + vehicles.join(',') : ''} @${fmt(time)}" }
    }

    final List<Entry> entries = new java.util.concurrent.CopyOnWriteArrayList()

    /** Seconds with at most three decimals and no trailing zeros: 0, 0.3, 1.25. */
    static String fmt(double seconds) {
        BigDecimal.valueOf(seconds).setScale(3, RoundingMode.HALF_UP).stripTrailingZeros().toPlainString()
    }

    void record(String kind, String task, List<String> vehicles, double time) {
        entries << new Entry(kind, task, vehicles, time)
    }

    /** The start, done, error and stop entries as strings such as "start a 1 @0". */
    List<String> lines() {
        entries.findAll { !(it.kind in ['init', 'step']) }*.toString()
    }

    /** The entries of the given kinds, as strings. */
    List<String> lines(String... kinds) {
        entries.findAll { it.kind in kinds }*.toString()
    }

    /** The clock times at which {@code task} was stepped. */
    List<String> stepTimes(String task) {
        entries.findAll { it.kind == 'step' && it.task == task }.collect { fmt(it.time) }
    }

    /** "task:v1,v2" for each init entry, in initialisation (tree) order. */
    List<String> allocations() {
        entries.findAll { it.kind == 'init' }.collect { "${it.task}:${it.vehicles.join(',')}".toString() }
    }

    int count(String kind, String task) {
        entries.count { it.kind == kind && it.task == task } as int
    }
}
