package dolphin.cli;

import dolphin.core.CompletionState;
import dolphin.core.TaskEvent;
import dolphin.mavlink.MAVLinkNode;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The status of every vehicle: telemetry from its node's snapshot, and the last platform task the
 * script ran on it, from the engine's task events (script thread; read by the display thread).
 */
final class StatusBoard {

    private final Map<String, String> tasks = new ConcurrentHashMap<>();

    void taskEvent(TaskEvent event) {
        if (!event.isPlatformTask()) {
            return;
        }
        String state = switch (event.kind()) {
            case STARTED -> "running";
            case STOPPED -> "stopped";
            case COMPLETED -> completed(event.state());
        };
        String text = event.task().getId() + " " + state;
        event.vehicles().forEach(v -> tasks.put(v, text));
    }

    /** "done", or "error: " and the error as written (vehicle modes and command names keep their case). */
    private static String completed(CompletionState state) {
        String type = state.getType().name().toLowerCase(Locale.ROOT);
        return state.getMessage() == null ? type : type + ": " + state.getMessage();
    }

    List<VehicleStatus> statuses(List<MAVLinkNode> nodes) {
        return nodes.stream().map(n -> VehicleStatus.of(n, tasks.getOrDefault(n.getId(), ""))).toList();
    }
}
