package dolphin.cli;

import java.util.List;

/** Where `dolphin run` shows its lines and the vehicles' status: a live terminal or a plain log. */
interface Screen {

    /** A timestamped line: a program message or a task event. */
    void line(String text);

    /** The vehicles' status now. */
    void refresh(List<VehicleStatus> statuses);
}
