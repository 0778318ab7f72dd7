package dolphin.mission.survey;

import java.util.Objects;

/**
 * How transects are flown (QGC's TransectStyleComplexItem, docs/qgc-surveys.md §2.6, §2.8, §2.9):
 * turnaround distance in m beyond each end, photos in the turnarounds, hover and capture, a
 * second pass at 90°, the altitude reference and the generation of items to emit.
 */
public record TransectOptions(double turnaround, boolean triggerInTurnarounds, boolean hoverAndCapture,
                              boolean refly90, HeightReference height, Emission emission) {

    public TransectOptions {
        if (!(turnaround >= 0) || Double.isInfinite(turnaround)) {
            throw new IllegalArgumentException("the turnaround distance must be 0 m or more, got "
                    + Numbers.format(turnaround));
        }
        Objects.requireNonNull(height, "height");
        Objects.requireNonNull(emission, "emission");
    }

    /** Turnaround 10 m, photos in turnarounds, no hover, no refly, above home, current QGC items. */
    public static TransectOptions defaults() {
        return new TransectOptions(10, true, false, false, HeightReference.ABOVE_HOME, Emission.CURRENT);
    }

    public TransectOptions withTurnaround(double metres) {
        return new TransectOptions(metres, triggerInTurnarounds, hoverAndCapture, refly90, height, emission);
    }

    public TransectOptions withTriggerInTurnarounds(boolean on) {
        return new TransectOptions(turnaround, on, hoverAndCapture, refly90, height, emission);
    }

    public TransectOptions withHoverAndCapture(boolean on) {
        return new TransectOptions(turnaround, triggerInTurnarounds, on, refly90, height, emission);
    }

    public TransectOptions withRefly90(boolean on) {
        return new TransectOptions(turnaround, triggerInTurnarounds, hoverAndCapture, on, height, emission);
    }

    public TransectOptions withHeight(HeightReference h) {
        return new TransectOptions(turnaround, triggerInTurnarounds, hoverAndCapture, refly90, h, emission);
    }

    public TransectOptions withEmission(Emission e) {
        return new TransectOptions(turnaround, triggerInTurnarounds, hoverAndCapture, refly90, height, e);
    }
}
