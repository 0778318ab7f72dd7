package dolphin.testing

import dolphin.core.Position

/** Reading a script run's lines (the executor's progress and the script's messages), for the examples and the SITL suite. */
final class ScriptLines {

    private ScriptLines() {
    }

    /** The vehicle a mission started on, from the executor's "mission M on vehicle N: started" line. */
    static int vehicleOf(List<String> lines, String mission) {
        String line = lines.find { it ==~ /mission ${mission} on vehicle \d+: started/ }
        assert line: "mission ${mission} never started:\n${lines.join('\n')}"
        (line =~ /vehicle (\d+)/)[0][1] as int
    }

    /** The index of the first line equal to {@code line} (or starting with it, when it ends with '*') after {@code from}. */
    static int after(List<String> lines, int from, String line) {
        int i = lines.findIndexOf(from + 1) { line.endsWith('*') ? it.startsWith(line[0..-2]) : it == line }
        assert i > from: "no line '${line}' after line ${from}:\n${lines.join('\n')}"
        i
    }

    /** Each line appears, in this order; fails with the output if one does not. */
    static boolean inOrder(List<String> lines, String... expected) {
        int i = -1
        expected.each { i = after(lines, i, it) }
        true
    }

    static Position parsePosition(String text) {
        def m = text =~ /\((-?[\d.]+)°, (-?[\d.]+)°, (-?[\d.]+)\)/
        assert m.find(): "no position in '${text}'"
        Position.fromDegrees(m.group(1) as double, m.group(2) as double, m.group(3) as double)
    }
}
