package dolphin.dsl

import dolphin.core.Area
import dolphin.core.NodeFilter
import dolphin.core.Position

/** The clauses of {@code pick { ... }}; a repeated clause replaces the earlier one. */
class Picker {
    int count = 1
    double timeout = 0
    private String id
    private String type
    private List<String> payload = []
    private Area area

    void count(int n) {
        if (n <= 0) {
            throw new DslException("pick: count must be positive, got ${n}")
        }
        count = n
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
        timeout = seconds.doubleValue()
    }

    NodeFilter filter() {
        new NodeFilter(id, type, payload, area)
    }
}
