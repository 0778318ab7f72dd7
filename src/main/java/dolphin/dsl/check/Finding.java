package dolphin.dsl.check;

/** A mistake the checker found: where (1-based line and column) and what. */
public record Finding(int line, int column, String message) {
}
