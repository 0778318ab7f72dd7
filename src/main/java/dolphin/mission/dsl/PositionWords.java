package dolphin.mission.dsl;

import dolphin.core.Position;
import dolphin.dsl.DslException;
import dolphin.dsl.vocabulary.Word;
import groovy.lang.Closure;
import groovy.lang.DelegatesTo;
import java.util.Arrays;
import java.util.stream.Collectors;

/**
 * The script-level {@code move} of the original plugin: {@code move(p, { north n;
 * east e; down d })} and {@code move(p, moveDistance { ... })}, a position displaced by an offset.
 *
 * <p>It is a platform word (resolved when nothing else answers), not a static import like
 * {@code pos} and {@code mission}: Groovy binds static imports at compile time, so a static
 * {@code move(Position, Closure)} would capture the mission command {@code move north, east} inside
 * {@code mission { }} blocks.
 */
public final class PositionWords {

    @Word("A position north, east and down of another: move(p, { north 10; east 5 })")
    public Position move(Position position, @DelegatesTo(value = NedBuilder.class, strategy = Closure.DELEGATE_FIRST) Closure<?> offset) {
        return NedBuilder.build("move", offset).from(Args.position("move", position));
    }

    @Word("A position north, east and down of another: move(p, { north 10; east 5 })")
    public Position move(Position position, NedOffset offset) {
        if (offset == null) {
            throw new DslException("move: the offset is null: expected moveDistance { north n; east e; down d }");
        }
        return offset.from(Args.position("move", position));
    }

    /** Any other arguments: say what move expects here, and that the mission command lives in mission { }. */
    public Position move(Object... args) {
        String got = Arrays.stream(args).map(a -> a == null ? "null" : a.getClass().getSimpleName())
                .collect(Collectors.joining(", ", "(", ")"));
        throw new DslException("move: expected (position, { north n; east e; down d }) or (position, moveDistance { ... }),"
                + " got " + got + "; move(north, east[, up]) is a mission command, for use inside mission { }");
    }
}
