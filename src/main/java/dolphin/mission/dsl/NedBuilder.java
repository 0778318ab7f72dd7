package dolphin.mission.dsl;

import groovy.lang.Closure;
import dolphin.dsl.vocabulary.Word;
import groovy.lang.DelegatesTo;
import java.util.Set;

/**
 * The delegate of {@code moveDistance { north n; east e; down d }} and {@code move(p) { ... }}: metres,
 * each 0 unless given. A negative value needs parentheses: {@code down(-10)}.
 */
public final class NedBuilder extends ClosureDelegate {

    private final String word;
    private double north;
    private double east;
    private double down;

    NedBuilder(String word) {
        super(word, Set.of("north", "east", "down"));
        this.word = word;
    }

    @Word("Metres north")
    public void north(Number metres) {
        north = Args.number(word, "north offset", metres);
    }

    @Word("Metres east")
    public void east(Number metres) {
        east = Args.number(word, "east offset", metres);
    }

    @Word("Metres down (negative: up)")
    public void down(Number metres) {
        down = Args.number(word, "down offset", metres);
    }

    NedOffset offset() {
        return new NedOffset(north, east, down);
    }

    /** Runs the closure with a new builder as its delegate. */
    static NedOffset build(String word,
            @DelegatesTo(value = NedBuilder.class, strategy = Closure.DELEGATE_FIRST) Closure<?> body) {
        NedBuilder b = new NedBuilder(word);
        b.run(body);
        return b.offset();
    }
}
