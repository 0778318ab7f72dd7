package dolphin.sim;

import java.util.List;

/** What the fleet's vehicles carry beside their autopilot: sensors, and cameras on some vehicles. */
public record SimEquipment(List<SimSensor> sensors, SysidSet cameras) {

    public static final SimEquipment NONE = new SimEquipment(List.of(), SysidSet.NONE);

    public SimEquipment {
        sensors = List.copyOf(sensors);
    }

    /** The sensors vehicle {@code sysid} carries. */
    List<SimSensor> sensorsOf(int sysid) {
        return sensors.stream().filter(s -> s.vehicles().contains(sysid)).toList();
    }

    boolean cameraOn(int sysid) {
        return cameras.contains(sysid);
    }
}
