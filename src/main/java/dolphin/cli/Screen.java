package dolphin.cli;

import java.util.List;

/** Where `dolphin run` shows its lines and the vehicles' status: a live terminal or a plain log. */
interface Screen {

    /** A timestamped line: a program message or a task event. */
    void line(String text);

    /** The vehicles' status now. */
    void refresh(List<VehicleStatus> statuses);

    /**
     * The status of the vehicles whose task just started or ended, at that moment. A log shows them
     * now, so it never misses the state a task started from, however fast the run; a live table
     * shows them at its next refresh.
     */
    default void taskChanged(List<VehicleStatus> statuses) {
    }
}
