package dolphin.mission.dsl;

import dolphin.dsl.DslException;
import dolphin.dsl.vocabulary.Word;
import dolphin.mission.model.Fence;
import dolphin.mission.survey.EntryCorner;
import dolphin.mission.survey.HeightReference;
import dolphin.mission.survey.PhotoGrid;
import dolphin.mission.survey.TransectOptions;
import java.util.Locale;
import java.util.Set;
import java.util.function.Supplier;

/**
 * The words of the blocks that fly straight lines with a camera, surveys and corridor scans: where
 * to start, how far to overshoot each line to turn, and how to take the photos.
 */
public abstract class TransectBuilder extends MappingBuilder {

    private EntryCorner entry = EntryCorner.TOP_LEFT;
    private TransectOptions options = TransectOptions.defaults();
    private double spacing = Double.NaN;
    private HeightReference height = HeightReference.ABOVE_HOME;

    TransectBuilder(String word, Set<String> words, Supplier<Fence> fence) {
        super(word, union(words, Set.of("spacing", "heightAbove", "entry", "turnaround", "triggerInTurnarounds")), fence);
    }

    @Word("Where the flight starts: 'topLeft' (the default), 'topRight', 'bottomLeft' or 'bottomRight', as QGroundControl names them")
    public void entry(String corner) {
        try {
            entry = EntryCorner.parse(corner);
        } catch (IllegalArgumentException e) {
            throw new DslException(word + ": entry: " + e.getMessage());
        }
    }

    @Word("Metres flown past each line's end to turn (default 10; 0: none)")
    public void turnaround(Number metres) {
        options = options.withTurnaround(Args.notNegative(word, "turnaround distance", metres));
    }

    /** Photos taken at stops instead of by distance (QGroundControl offers it for surveys). */
    final void hover() {
        options = options.withHoverAndCapture(true).withTriggerInTurnarounds(false);
    }

    @Word("true (the default): the camera keeps triggering through the turns; false: only along the lines")
    public void triggerInTurnarounds(boolean on) {
        options = options.withTriggerInTurnarounds(on);
    }

    @Word("Without a camera: metres between flight lines")
    public void spacing(Number metres) {
        once("spacing");
        spacing = Args.positive(word, "spacing", metres);
    }

    @Override
    final String manualWords(String altitudeWord) {
        return "'" + altitudeWord + " METRES', 'spacing METRES' and 'triggerDistance METRES'";
    }

    @Override
    final boolean manualWordsSaid() {
        return said("spacing") || said("triggerDistance");
    }

    @Override
    final PhotoGrid manualGrid(double altitude) {
        if (Double.isNaN(spacing)) {
            throw new DslException(word + ": without a camera, say how far apart the lines are: 'spacing METRES'");
        }
        return PhotoGrid.manual(altitude, spacing, manualTriggerDistance());
    }

    @Word("What the altitude is measured from: 'home' (the default), 'sea level' or 'terrain'")
    public void heightAbove(String reference) {
        String r = reference == null ? "" : reference.trim().toLowerCase(Locale.ROOT).replace('_', ' ');
        height = switch (r) {
            case "home" -> HeightReference.ABOVE_HOME;
            case "sea level", "sealevel", "amsl" -> HeightReference.ABOVE_SEA_LEVEL;
            case "terrain", "ground" -> HeightReference.ABOVE_TERRAIN;
            default -> throw new DslException(word + ": heightAbove: expected 'home', 'sea level' or 'terrain', got '"
                    + reference + "'");
        };
    }

    final EntryCorner entryCorner() {
        return entry;
    }

    final TransectOptions options() {
        return options.withHeight(height);
    }
}
