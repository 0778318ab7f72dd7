package dolphin.mission.survey;

import com.MAVLink.enums.MAV_CMD;
import dolphin.mission.model.MissionItem;
import dolphin.mission.survey.TransectPoint.PointKind;
import java.util.ArrayList;
import java.util.List;

/**
 * The mission items of a transect survey in one of QGroundControl's emission generations
 * (docs/qgc-surveys.md §2.8): a waypoint per flown coordinate at the survey altitude, with camera
 * trigger commands between them.
 */
final class ItemEmitter {

    /** How long a hover-and-capture stop holds, s (current QGC's _hoverAndCaptureDelaySeconds). */
    static final float HOVER_HOLD = 4;

    private final int frame;
    private final float altitude;
    private final float trigger;
    private final TransectOptions options;
    private final List<MissionItem> items = new ArrayList<>();
    private int seq;

    private ItemEmitter(int seq, PhotoGrid grid, TransectOptions options) {
        this.seq = seq;
        this.frame = options.height().frame();
        this.altitude = (float) grid.altitude();
        this.trigger = (float) grid.triggerDistance();
        this.options = options;
    }

    static List<MissionItem> emit(int seq, List<List<TransectPoint>> transects, PhotoGrid grid, TransectOptions options) {
        ItemEmitter e = new ItemEmitter(seq, grid, options);
        if (options.hoverAndCapture() && e.triggers()) {
            // hover and capture takes photos at stops, with no distance triggering, in every generation
            e.hovering(transects);
        } else {
            switch (options.emission()) {
                case CURRENT, CURRENT_NO_LABEL_SWAP -> e.current(transects);
                case LEGACY_SURVEY -> e.legacySurvey(transects);
                case LEGACY_CORRIDOR -> e.legacyCorridor(transects);
            }
        }
        return List.copyOf(e.items);
    }

    private boolean triggers() {
        return trigger != 0;
    }

    /** Generation C: the trigger restarts at every entry so that a resumed mission refills its transect. */
    private void current(List<List<TransectPoint>> transects) {
        List<TransectPoint> path = flat(transects);
        boolean inTurnarounds = options.triggerInTurnarounds();
        boolean firstAndLast = inTurnarounds && triggers();
        boolean turnarounds = options.turnaround() != 0;
        for (int i = 0; i < path.size(); i++) {
            TransectPoint p = path.get(i);
            boolean first = i == 0;
            boolean last = i == path.size() - 1;
            waypoint(p, 0);
            switch (p.kind()) {
                case TURNAROUND -> {
                    if (firstAndLast && first) {
                        trig(trigger, 1);
                    }
                    if (firstAndLast && last) {
                        trig(0, 1);
                    }
                }
                case ENTRY -> {
                    if (triggers()) {
                        trig(trigger, 1);
                    }
                }
                case EXIT -> {
                    if (triggers() && (!inTurnarounds || (!turnarounds && last))) {
                        trig(0, 1);
                    }
                }
                case INTERIOR, HOVER -> {
                }
            }
        }
    }

    /** Generation A: with photos in turnarounds one start after the first waypoint and one stop at the end. */
    private void legacySurvey(List<List<TransectPoint>> transects) {
        List<TransectPoint> path = flat(transects);
        boolean inTurnarounds = options.triggerInTurnarounds();
        for (int i = 0; i < path.size(); i++) {
            TransectPoint p = path.get(i);
            waypoint(p, 0);
            if (!triggers()) {
                continue;
            }
            if (inTurnarounds && i == 0) {
                trig(trigger, 1);
            }
            if (!inTurnarounds && p.kind() == PointKind.ENTRY) {
                trig(trigger, 1);
            }
            if (!inTurnarounds && p.kind() == PointKind.EXIT) {
                trig(0, 0);
            }
        }
        if (triggers() && inTurnarounds) {
            trig(0, 0);
        }
    }

    /**
     * Generation B: a start at each transect's first camera-section end whatever its label, a
     * stop at its second one unless photos go on in the turnarounds.
     */
    private void legacyCorridor(List<List<TransectPoint>> transects) {
        boolean inTurnarounds = options.triggerInTurnarounds();
        boolean first = true;
        for (List<TransectPoint> t : transects) {
            boolean started = false;
            for (TransectPoint p : t) {
                waypoint(p, 0);
                if (triggers() && first && inTurnarounds) {
                    trig(trigger, 1);
                }
                first = false;
                if (triggers() && (p.kind() == PointKind.ENTRY || p.kind() == PointKind.EXIT)) {
                    if (!started) {
                        trig(trigger, 1);
                        started = true;
                    } else if (!inTurnarounds) {
                        trig(0, 0);
                    }
                }
            }
        }
        if (triggers() && inTurnarounds) {
            trig(0, 0);
        }
    }

    /** Hover and capture: stop and take one photo at the entry, each hover point and the exit. */
    private void hovering(List<List<TransectPoint>> transects) {
        for (TransectPoint p : flat(transects)) {
            boolean shoot = p.kind() == PointKind.ENTRY || p.kind() == PointKind.HOVER || p.kind() == PointKind.EXIT;
            waypoint(p, shoot ? HOVER_HOLD : 0);
            if (shoot) {
                items.add(MissionItem.command(seq++, MAV_CMD.MAV_CMD_IMAGE_START_CAPTURE, 0, 0, 1, 0));
            }
        }
    }

    static List<TransectPoint> flat(List<List<TransectPoint>> transects) {
        List<TransectPoint> out = new ArrayList<>();
        transects.forEach(out::addAll);
        return out;
    }

    private void waypoint(TransectPoint p, float hold) {
        items.add(new MissionItem(seq++, MAV_CMD.MAV_CMD_NAV_WAYPOINT, frame, hold, 0, 0, Float.NaN,
                MissionItem.degE7(p.latitude()), MissionItem.degE7(p.longitude()), altitude, true));
    }

    private void trig(float distance, float p3) {
        items.add(MissionItem.command(seq++, MAV_CMD.MAV_CMD_DO_SET_CAM_TRIGG_DIST, distance, 0, p3, 0));
    }
}
