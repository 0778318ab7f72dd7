package dolphin.web;

import dolphin.core.Node;
import dolphin.mavlink.MAVLinkNode;
import dolphin.sensor.SensorService;
import dolphin.mission.file.GeoJsonFile;
import dolphin.mission.model.Mission;
import dolphin.mission.flight.MissionExecutor;
import dolphin.mission.flight.MissionService;
import dolphin.mission.file.MissionFile;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Supplier;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/** Samples the MAVLink platform's vehicles: each node's snapshot, whether the script holds it, its mission, the name of its link. */
final class MavlinkFleet implements Supplier<List<VehicleSample>> {

    private static final Logger LOG = LoggerFactory.getLogger(MavlinkFleet.class);

    private final Supplier<List<MAVLinkNode>> nodes;
    private final Supplier<? extends Iterable<Node>> picked;
    private final TaskBoard board;

    MavlinkFleet(Supplier<List<MAVLinkNode>> nodes, Supplier<? extends Iterable<Node>> picked, TaskBoard board) {
        this.nodes = nodes;
        this.picked = picked;
        this.board = board;
    }

    @Override
    public List<VehicleSample> get() {
        Set<String> bound = new HashSet<>();
        picked.get().forEach(n -> bound.add(n.getId()));
        Map<String, String> tasks = board.vehicleTasks();
        List<VehicleSample> samples = new ArrayList<>();
        for (MAVLinkNode n : nodes.get()) {
            int silence = n.silence().map(d -> (int) d.toSeconds()).orElse(-1);
            VehicleView view = VehicleView.of(n.getId(), n.getType(), n.isConnected(), silence, bound.contains(n.getId()), n.state(),
                    tasks.getOrDefault(n.getId(), ""), n.getPayload().names(), readings(n),
                    MissionService.of(n.communications()).transferOn(n).orElse(null), n.getLink() == null ? null : n.getLink().toString());
            MissionExecutor executor = MissionService.of(n.communications()).executorOn(n);
            samples.add(new VehicleSample(view, executor, () -> draw(executor.mission(), n)));
        }
        return samples;
    }

    private static List<VehicleView.Shown> readings(MAVLinkNode n) {
        long now = n.communications().clock().nanoTime();
        return SensorService.of(n.communications()).readings(n).all().stream()
                .map(r -> new VehicleView.Shown(r.name(), r.value(), r.unit(), r.component(), r.fresh(now))).toList();
    }

    /** The mission, its fence and rally points as GeoJSON (docs/embedding.md); null if it cannot be drawn. */
    private static String draw(Mission m, MAVLinkNode node) {
        try {
            return GeoJsonFile.compact(m.getId(), MissionFile.of(m, m.items(node.getHome())));
        } catch (RuntimeException e) {
            LOG.debug("mission {} of vehicle {} not drawn: {}", m.getId(), node.getId(), e.getMessage());
            return null;
        }
    }
}
