package dolphin.cli;

import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.function.Supplier;
import java.util.stream.Collectors;

/**
 * A terminal display: lines scroll as usual, and below them a table with a row per vehicle is
 * redrawn in place (ANSI cursor movement). A large fleet shows its first {@code maxRows} vehicles
 * and one summary row of the others by mode.
 */
final class LiveScreen implements Screen {

    private static final String UP_AND_CLEAR = "\033[%dF\033[J";

    private final PrintWriter out;
    private final Supplier<String> stamp;
    private final int maxRows;
    private List<String> board = List.of();

    LiveScreen(PrintWriter out, Supplier<String> stamp, int maxRows) {
        this.out = out;
        this.stamp = stamp;
        this.maxRows = maxRows;
    }

    @Override
    public synchronized void line(String text) {
        erase();
        out.println(stamp.get() + text);
        draw();
    }

    /** A line that comes with its own timestamp (a log line), above the table. */
    synchronized void above(String text) {
        erase();
        out.println(text);
        draw();
    }

    @Override
    public synchronized void refresh(List<VehicleStatus> statuses) {
        erase();
        board = table(statuses);
        draw();
    }

    List<String> table(List<VehicleStatus> statuses) {
        if (statuses.isEmpty()) {
            return List.of("no vehicles yet");
        }
        List<String> rows = new ArrayList<>();
        rows.add(VehicleStatus.HEADER);
        statuses.stream().limit(maxRows).map(VehicleStatus::row).forEach(rows::add);
        if (statuses.size() > maxRows) {
            Map<String, Long> modes = statuses.stream().skip(maxRows)
                    .collect(Collectors.groupingBy(VehicleStatus::modeGroup, TreeMap::new, Collectors.counting()));
            rows.add("... and " + (statuses.size() - maxRows) + " more: " + modes.entrySet().stream()
                    .map(e -> e.getValue() + " " + e.getKey()).collect(Collectors.joining(", ")));
        }
        return rows;
    }

    private void erase() {
        if (!board.isEmpty()) {
            out.printf(UP_AND_CLEAR, board.size());
        }
    }

    private void draw() {
        board.forEach(out::println);
        out.flush();
    }
}
