package dolphin.editor;

/**
 * Where a script gives a name its first value: {@code surveyNorth = mission { }}, {@code def x},
 * {@code def cutAt(v) { }}.
 *
 * @param name the name
 * @param offset where the name is written there
 * @param method whether it names a method ({@code def cutAt(v)}) rather than a variable
 */
record NamedPlace(String name, int offset, boolean method) {
}
