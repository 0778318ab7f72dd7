package dolphin.cli;

import java.io.PrintWriter;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;

/**
 * Plain lines for logs and pipes: each line as it comes, and a line for a vehicle whenever its mode,
 * arming, connection or task changes (battery, height and mission item alone do not make a line).
 */
final class PlainScreen implements Screen {

    private final PrintWriter out;
    private final Supplier<String> stamp;
    private final Map<String, VehicleStatus> shown = new HashMap<>();

    PlainScreen(PrintWriter out, Supplier<String> stamp) {
        this.out = out;
        this.stamp = stamp;
    }

    @Override
    public synchronized void line(String text) {
        out.println(stamp.get() + text);
        out.flush();
    }

    @Override
    public synchronized void refresh(List<VehicleStatus> statuses) {
        for (VehicleStatus s : statuses) {
            if (!s.sameEvent(shown.put(s.id(), s))) {
                line(s.sentence());
            }
        }
    }

    @Override
    public void taskChanged(List<VehicleStatus> statuses) {
        refresh(statuses);
    }
}
