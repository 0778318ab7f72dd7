package dolphin.web;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;

/**
 * The web view's event log: the script's messages, task events, the vehicles' STATUSTEXT and their
 * events (contact lost and regained), errors, numbered from 1, the last {@code capacity} kept.
 * Written by the script and communications threads, read by the viewers' threads; a viewer asks for
 * what came after the last number it has.
 */
final class EventLog {

    /** One line of the log; {@code vehicle} is null for lines that are not a vehicle's. */
    record Entry(long seq, double time, String kind, String vehicle, String text) {
    }

    /** The entries after a number, and how many between it and them are no longer kept. */
    record Since(List<Entry> entries, long lost) {
    }

    private final int capacity;
    private final ArrayDeque<Entry> entries = new ArrayDeque<>();
    private long last;

    EventLog(int capacity) {
        this.capacity = capacity;
    }

    synchronized void add(double time, String kind, String vehicle, String text) {
        entries.addLast(new Entry(++last, time, kind, vehicle, text));
        if (entries.size() > capacity) {
            entries.removeFirst();
        }
    }

    synchronized long last() {
        return last;
    }

    synchronized Since since(long seq) {
        List<Entry> after = new ArrayList<>();
        for (Entry e : entries) {
            if (e.seq() > seq) {
                after.add(e);
            }
        }
        long first = after.isEmpty() ? last + 1 : after.get(0).seq();
        return new Since(after, Math.max(0, first - seq - 1));
    }
}
