package dolphin.dsl;

import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.Map;
import java.util.Set;
import java.util.function.Predicate;

/** The signals of {@code post}, {@code consume} and {@code poll}: a set of values per key, one per script run. */
public final class SignalSet {

    private final Map<String, Set<Object>> signals = new LinkedHashMap<>();

    public synchronized void post(Map<String, ?> pairs) {
        pairs.forEach((k, v) -> signals.computeIfAbsent(k, x -> new LinkedHashSet<>()).add(v));
    }

    /** True only if every pair is present; then all of them are removed. */
    public synchronized boolean consume(Map<String, ?> pairs) {
        for (Map.Entry<String, ?> e : pairs.entrySet()) {
            Set<Object> values = signals.get(e.getKey());
            if (values == null || !values.contains(e.getValue())) {
                return false;
            }
        }
        pairs.forEach((k, v) -> {
            Set<Object> values = signals.get(k);
            values.remove(v);
            if (values.isEmpty()) {
                signals.remove(k);
            }
        });
        return true;
    }

    public synchronized boolean poll(String key) {
        return signals.containsKey(key);
    }

    /** True if, for every key, some value of that key satisfies its predicate. */
    public synchronized boolean poll(Map<String, Predicate<Object>> tests) {
        for (Map.Entry<String, Predicate<Object>> e : tests.entrySet()) {
            Set<Object> values = signals.getOrDefault(e.getKey(), Set.of());
            if (values.stream().noneMatch(e.getValue())) {
                return false;
            }
        }
        return true;
    }

    public synchronized void clear() {
        signals.clear();
    }

    @Override
    public synchronized String toString() {
        return signals.toString();
    }
}
