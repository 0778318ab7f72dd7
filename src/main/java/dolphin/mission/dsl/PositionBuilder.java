package dolphin.mission.dsl;

import dolphin.core.Position;
import dolphin.dsl.vocabulary.Word;
import groovy.lang.Closure;
import groovy.lang.DelegatesTo;
import java.util.Set;

/**
 * The delegate of {@code pos { lat x; lon y; hae h }}: degrees and metres above mean
 * sea level; {@code height} is another name for {@code hae}. Each is 0 unless given. A negative value
 * needs parentheses: {@code lon(-8.6)}.
 */
public final class PositionBuilder extends ClosureDelegate {

    private Number lat = 0;
    private Number lon = 0;
    private Number hae = 0;

    PositionBuilder() {
        super("pos", Set.of("lat", "lon", "hae", "height"));
    }

    @Word("Latitude, degrees")
    public void lat(Number degrees) {
        lat = degrees;
    }

    @Word("Longitude, degrees")
    public void lon(Number degrees) {
        lon = degrees;
    }

    @Word("Height above the WGS-84 ellipsoid (mean sea level), metres")
    public void hae(Number metres) {
        hae = metres;
    }

    @Word("Another name for hae: metres above mean sea level")
    public void height(Number metres) {
        hae = metres;
    }

    Position position() {
        return Args.position("pos", lat, lon, hae);
    }

    static Position build(@DelegatesTo(value = PositionBuilder.class, strategy = Closure.DELEGATE_FIRST) Closure<?> body) {
        PositionBuilder b = new PositionBuilder();
        b.run(body);
        return b.position();
    }
}
