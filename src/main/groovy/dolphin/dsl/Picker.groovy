package dolphin.dsl

import dolphin.core.Area
import dolphin.core.NodeFilter
import dolphin.core.Position
import dolphin.dsl.vocabulary.Word

/** The clauses of {@code pick { ... }}; a repeated clause replaces the earlier one. */
class Picker {
    private static final List<String> CLAUSES = ['count', 'timeout', 'type', 'id', 'payload', 'region']

    private int requestedCount = 1
    private double requestedTimeout = 0
    private String id
    private String type
    private List<String> payload = []
    private Area area

    @Word('How many vehicles to pick (1 unless given)')
    void count(int n) {
        if (n <= 0) {
            throw new DslException("pick: count must be positive, got ${n}")
        }
        requestedCount = n
    }

    @Word('The vehicles\' Dolphin type: \'UAV\', \'UGV\', \'USV\', \'UUV\'')
    void type(String name) { type = name }

    @Word('The vehicle with this id (its MAVLink system id) or the name a fleet file gives it')
    void id(Object systemId) { id = String.valueOf(systemId) }

    @Word('Vehicles that carry all these payloads')
    void payload(String... names) { payload = names as List }

    @Word('Vehicles inside this area')
    void region(Area area) { this.area = area }

    @Word('Vehicles inside this area')
    void region(Position center, Number radius) { area = new Area(center, radius.doubleValue()) }

    @Word('How long to wait for such vehicles, in seconds (0: only those there now)')
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
