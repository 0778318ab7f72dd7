package dolphin.sensor;

import java.util.Set;
import java.util.TreeSet;

/**
 * The sensor names known before any vehicle speaks: those a fleet file lists, and those sensor classes
 * declare ({@link Sensor#names()}). A fleet file's list (or a script's {@code declareSensors}) turns on
 * the unknown-name check; names of classes only widen what it accepts.
 */
public record DeclaredSensors(Set<String> fleet, Set<String> classes) {

    public static final DeclaredSensors NONE = new DeclaredSensors(Set.of(), Set.of());

    public DeclaredSensors {
        fleet = Set.copyOf(fleet);
        classes = Set.copyOf(classes);
    }

    /** The fleet file's names and the installed sensors' names. */
    public static DeclaredSensors of(FleetFile fleet) {
        Set<String> classes = new TreeSet<>();
        SensorService.installed().forEach(s -> classes.addAll(s.names()));
        return new DeclaredSensors(fleet.sensorNames(), classes);
    }

    /** Every name, sorted. */
    public Set<String> all(Set<String> alsoDeclared) {
        Set<String> names = new TreeSet<>(fleet);
        names.addAll(classes);
        names.addAll(alsoDeclared);
        return names;
    }
}
