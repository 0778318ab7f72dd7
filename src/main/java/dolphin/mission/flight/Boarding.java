package dolphin.mission.flight;

import dolphin.mission.model.FlightWay;
import dolphin.mission.model.Underwater;
import java.util.Map;
import java.util.OptionalDouble;
import java.util.function.IntFunction;

/**
 * What a family's {@link FlightRules#onBoard} may need beside the items: the mission's water (null
 * above it), how the script wants each take-off and landing flown, by item seq, and the vehicle's
 * parameters that the family asked for ({@link FlightRules#parameters()}), each empty when the
 * vehicle did not give it.
 */
record Boarding(Underwater water, IntFunction<FlightWay> wayOf, Map<String, OptionalDouble> parameters) {

    /** A parameter's value, or empty when the vehicle did not give it. */
    OptionalDouble parameter(String name) {
        return parameters.getOrDefault(name, OptionalDouble.empty());
    }
}
