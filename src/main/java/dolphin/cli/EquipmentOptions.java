package dolphin.cli;

import dolphin.sim.SimEquipment;
import dolphin.sim.SimSensor;
import dolphin.sim.SysidSet;
import java.io.IOException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import picocli.CommandLine;
import picocli.CommandLine.ParameterException;

/**
 * The simulated fleet's sensors and cameras from the options of {@code dolphin sim} ({@code --sensor},
 * {@code --camera}, {@code --config}) or {@code dolphin run} (the same with {@code --sim-}): the
 * file's and the options' together. A bad one is a usage error naming the option or file, the
 * entry and what was expected.
 *
 * @param names the command's names of the sensor, camera and file options
 */
record EquipmentOptions(OptionNames names, List<String> sensors, String cameras, Path file) {

    record OptionNames(String sensor, String camera, String config) {
        static final OptionNames SIM = new OptionNames("--sensor", "--camera", "--config");
        static final OptionNames RUN = new OptionNames("--sim-sensor", "--sim-camera", "--sim-config");

        List<String> all() {
            return List.of(sensor, camera, config);
        }
    }

    static final String SENSOR_HELP = "A sensor on the simulated vehicles, sent as NAMED_VALUE_FLOAT NAME at 2 Hz: "
            + "NAME:plume:LAT,LON,RADIUS,PEAK[,BACKGROUND] (PEAK at the centre, falling to 0 at RADIUS metres) or "
            + "NAME:field:LAT,LON,BASE,GRADIENT,BEARING (BASE at LAT,LON, rising GRADIENT per metre towards BEARING degrees); "
            + "@SYSID[+SYSID...] after it puts it on those vehicles only (default: all). Fields of one name add up. Repeatable.";
    static final String CAMERA_HELP = "Simulated vehicles with a camera, answering a request for CAMERA_INFORMATION: "
            + "SYSID[+SYSID...] or all (default: none).";
    static final String CONFIG_HELP = "Sensors and cameras of the simulated vehicles from a JSON file (docs/guide.md), "
            + "besides those of the options.";

    EquipmentOptions {
        sensors = List.copyOf(sensors);
    }

    /** What the options give the vehicles with system ids {@code first..last}. */
    SimEquipment equipment(CommandLine cl, int first, int last) {
        List<SimSensor> all = new ArrayList<>();
        SysidSet withCamera = SysidSet.NONE;
        if (file != null) {
            SimEquipment fromFile = read(cl);
            for (int i = 0; i < fromFile.sensors().size(); i++) {
                SimSensor s = fromFile.sensors().get(i);
                inFleet(cl, names.config() + " " + file + ": sensors[" + i + "]: " + s.name(), s.vehicles(), first, last);
            }
            inFleet(cl, names.config() + " " + file + ": cameras", fromFile.cameras(), first, last);
            all.addAll(fromFile.sensors());
            withCamera = fromFile.cameras();
        }
        for (String spec : sensors) {
            String where = names.sensor() + " '" + spec + "'";
            SimSensor s;
            try {
                s = EquipmentText.sensor(spec);
            } catch (IllegalArgumentException e) {
                throw new ParameterException(cl, where + ": " + e.getMessage());
            }
            inFleet(cl, where, s.vehicles(), first, last);
            all.add(s);
        }
        if (cameras != null) {
            String where = names.camera() + " '" + cameras + "'";
            SysidSet given;
            try {
                given = EquipmentText.vehicles(cameras);
            } catch (IllegalArgumentException e) {
                throw new ParameterException(cl, where + ": " + e.getMessage());
            }
            inFleet(cl, where, given, first, last);
            withCamera = withCamera.union(given);
        }
        return new SimEquipment(all, withCamera);
    }

    private SimEquipment read(CommandLine cl) {
        try {
            return EquipmentFile.read(file);
        } catch (NoSuchFileException e) {
            throw new ParameterException(cl, names.config() + " " + file + ": no such file");
        } catch (IOException e) {
            throw new ParameterException(cl, names.config() + " " + file + ": cannot read it: " + e.getMessage());
        } catch (IllegalArgumentException e) {
            throw new ParameterException(cl, names.config() + " " + file + ": " + e.getMessage());
        }
    }

    /** A system id the fleet does not have is a mistake, not a sensor nobody carries. */
    static void inFleet(CommandLine cl, String where, SysidSet vehicles, int first, int last) {
        Set<Integer> outside = vehicles.outside(first, last);
        if (!outside.isEmpty()) {
            throw new ParameterException(cl, where + ": no vehicle with system id " + outside.iterator().next()
                    + " in the fleet (" + first + ".." + last + ")");
        }
    }
}
