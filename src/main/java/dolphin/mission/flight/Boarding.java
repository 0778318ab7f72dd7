package dolphin.mission.flight;

import dolphin.mission.model.FlightWay;
import dolphin.mission.model.Underwater;
import java.util.Map;
import java.util.OptionalDouble;

/**
 * What a family's {@link FlightRules#onBoard} may need beside the items: the mission's water (null
 * above it), the take-offs and landings the script says how to fly, by item seq, and the vehicle's
 * parameters that the family asked for ({@link FlightRules#parameters()}), each empty when the
 * vehicle did not give it.
 */
record Boarding(Underwater water, Map<Integer, FlightWay> ways, Map<String, OptionalDouble> parameters) {

    /** How the item at {@code seq} is to be flown: as the vehicle does unless the script says. */
    FlightWay way(int seq) {
        return ways.getOrDefault(seq, FlightWay.AS_THE_VEHICLE_DOES);
    }

    /** A parameter's value, or empty when the vehicle did not give it. */
    OptionalDouble parameter(String name) {
        return parameters.getOrDefault(name, OptionalDouble.empty());
    }
}
