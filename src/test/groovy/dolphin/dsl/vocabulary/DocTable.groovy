package dolphin.dsl.vocabulary

import java.nio.file.Files
import java.nio.file.Path

/** The first Markdown table under a heading of a docs page: its rows, each with its line number and cells. */
final class DocTable {

    /** One row: where it is and its cells, trimmed, escaped pipes read as pipes. */
    static final class Row {
        String doc
        int line
        List<String> cells

        String getWhere() { "${doc}:${line}" }

        /** The code spans of a cell: `goPos(lat, lon)`, `home(position)`. */
        List<String> code(int column) {
            (cells[column] =~ /`([^`]+)`/).collect { it[1] }
        }
    }

    final String doc
    final String heading
    final List<Row> rows

    private DocTable(String doc, String heading, List<Row> rows) {
        this.doc = doc
        this.heading = heading
        this.rows = rows
    }

    /**
     * The table under the line {@code heading}, the first such line after {@code after} when given;
     * null when there is no such heading or no table before the next heading.
     */
    static DocTable under(String doc, String heading, String after = null) {
        List<String> lines = Files.readAllLines(Path.of(doc))
        int from = after == null ? 0 : lines.indexOf(after)
        int at = from < 0 ? -1 : lines.findIndexOf(from) { it == heading }
        if (at < 0) {
            return null
        }
        List<Row> rows = []
        boolean started = false
        for (int i = at + 1; i < lines.size() && !lines[i].startsWith('#'); i++) {
            String line = lines[i]
            if (!line.startsWith('|')) {
                if (started) {
                    break
                }
                continue
            }
            started = true
            if (line ==~ /^\|[-| :]+\|$/) {
                continue
            }
            List<String> cells = line.substring(1, line.length() - 1).split(/(?<!\\)\|/).collect { it.trim().replace('\\|', '|') }
            rows << new Row(doc: doc, line: i + 1, cells: cells)
        }
        rows ? new DocTable(doc, heading, rows.drop(1)) : null
    }

    /** The usage as the vocabulary writes it: the docs' defaults ({@code [, hae = 0]}) left out. */
    static String withoutDefaults(String usage) {
        usage.replaceAll(/\s*=\s*[^,\[\]()]+/, '')
    }
}
