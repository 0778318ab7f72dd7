package dolphin.dsl

import dolphin.core.Area
import dolphin.core.NodeFilter
import dolphin.core.Position

/** The clauses of {@code pick { ... }}; a repeated clause replaces the earlier one. */
class Picker {
    private static final List<String> CLAUSES = ['count', 'timeout', 'type', 'id', 'payload', 'region']

    private int requestedCount = 1
    private double requestedTimeout = 0
    private String id
    private String type
    private List<String> payload = []
    private Area area

    void count(int n) {
        if (n <= 0) {
            throw new DslException("pick: count must be positive, got ${n}")
        }
        requestedCount = n
    }

    void type(String t) { type = t }

    void id(Object i) { id = String.valueOf(i) }

    void payload(String... names) { payload = names as List }

    void region(Area a) { area = a }

    void region(Position center, Number radius) { area = new Area(center, radius.doubleValue()) }

    void timeout(Number seconds) {
        if (seconds.doubleValue() < 0) {
            throw new DslException("pick: timeout must not be negative, got ${seconds}")
        }
        requestedTimeout = seconds.doubleValue()
    }

    int requestedCount() { requestedCount }

    double requestedTimeout() { requestedTimeout }

    /**
     * A clause read as a value is a mistake, mostly {@code count -2}, which Groovy reads as
     * "count minus 2"; other names go on to the script (its variables).
     */
    def propertyMissing(String name) {
        if (name in CLAUSES) {
            throw new DslException("pick: '${name}' is a clause and needs its value after it, e.g. '${name} 2';"
                    + " a negative value needs parentheses, '${name}(-2)' (Groovy reads '${name} -2' as '${name} minus 2')")
        }
        throw new MissingPropertyException(name, Picker)
    }

    NodeFilter filter() {
        new NodeFilter(id, type, payload, area)
    }
}
