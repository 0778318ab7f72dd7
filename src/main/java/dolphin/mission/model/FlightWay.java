package dolphin.mission.model;

/**
 * How a take-off or a landing is flown, where a vehicle can do both (a QuadPlane: docs/vtol.md).
 * The plain words leave it to the vehicle: a QuadPlane takes off and lands vertically, a plane on
 * its runway, a copter vertically. The explicit words say it, and a vehicle that cannot fly it that
 * way refuses the mission before it is uploaded.
 */
public enum FlightWay {
    AS_THE_VEHICLE_DOES("as the vehicle does"),
    VERTICAL("vertically"),
    RUNWAY("on a runway");

    private final String text;

    FlightWay(String text) {
        this.text = text;
    }

    @Override
    public String toString() {
        return text;
    }
}
