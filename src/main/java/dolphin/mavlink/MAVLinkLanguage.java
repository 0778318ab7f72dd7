package dolphin.mavlink;

import com.MAVLink.Messages.MAVLinkMessage;
import dolphin.core.Node;
import dolphin.core.NodeSet;
import dolphin.dsl.DslException;
import dolphin.dsl.DslExtension;
import dolphin.dsl.ScriptContext;
import dolphin.mavlink.codec.MessageTable;
import dolphin.mavlink.dsl.PositionWords;
import dolphin.core.EnvironmentException;
import dolphin.mavlink.mission.Mission;
import dolphin.mavlink.mission.MissionItem;
import dolphin.mavlink.mission.RawItemPoint;
import dolphin.mavlink.mission.TransferResult;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import org.codehaus.groovy.control.customizers.ImportCustomizer;

/**
 * What the MAVLink platform adds to the language: the generated message classes and enums imported
 * into scripts, the words {@code mission { }}, {@code pos { }} and {@code moveDistance { }} (static
 * imports of {@code dolphin.mavlink.dsl.MissionDsl}, so IDEs see them), {@code move(position, { })}
 * ({@link PositionWords}), {@code sendMessage(vehicles, message)} and {@code downloadMission(vehicle)}. Usable without a link, e.g. to
 * check scripts or build missions without vehicles.
 */
public final class MAVLinkLanguage implements DslExtension {

    @Override
    public void addImports(ImportCustomizer imports) {
        imports.addStarImports("com.MAVLink.minimal", "com.MAVLink.standard", "com.MAVLink.common",
                "com.MAVLink.ardupilotmega", "com.MAVLink.enums", "com.MAVLink.Messages");
        // named by string: MissionDsl is a Groovy class, compiled after the Java sources
        imports.addStaticStars("dolphin.mavlink.dsl.MissionDsl");
    }

    @Override
    public List<Object> words(ScriptContext context) {
        return List.of(new Words(context), new PositionWords());
    }

    /** The platform's DSL words. */
    public static final class Words {
        /** How long, in real time, downloadMission waits at most (the transfer itself times out sooner). */
        static final java.time.Duration DOWNLOAD_DEADLINE = java.time.Duration.ofSeconds(120);
        private final ScriptContext context;

        Words(ScriptContext context) {
            this.context = context;
        }

        /** Sends a raw MAVLink message to every vehicle of the set, at once (not a task). */
        public void sendMessage(NodeSet vehicles, MAVLinkMessage message) {
            for (Node n : vehicles) {
                if (!(n instanceof MAVLinkNode node)) {
                    throw new DslException("sendMessage: vehicle " + n.getId() + " is not a MAVLink vehicle");
                }
                node.send(message);
                context.listener().message("sent " + MessageTable.get().name(message.msgid) + " to vehicle " + node.getId());
            }
        }

        /**
         * The vehicle's current mission, downloaded (MISSION_REQUEST_LIST ...), as a Mission whose
         * home is the vehicle's item 0 and whose points are its items 1, 2, ... Blocks the script
         * until the download ends; fails with the download's error.
         */
        public Mission downloadMission(Object vehicle) {
            MAVLinkNode node = single(vehicle);
            TransferResult r;
            try {
                r = node.getDownloadProtocol().download().get(DOWNLOAD_DEADLINE.toSeconds(), TimeUnit.SECONDS);
            } catch (TimeoutException e) {
                throw new EnvironmentException("downloadMission: no answer from vehicle " + node.getId() + " within "
                        + DOWNLOAD_DEADLINE.toSeconds() + " s");
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new EnvironmentException("downloadMission: interrupted while downloading from vehicle " + node.getId());
            } catch (ExecutionException e) {
                throw new EnvironmentException("downloadMission: " + e.getCause());
            }
            List<MissionItem> items = r.orThrow();
            context.listener().message("downloaded " + items.size() + " mission items from vehicle " + node.getId());
            return RawItemPoint.mission("mission of vehicle " + node.getId(), items);
        }

        private static MAVLinkNode single(Object vehicle) {
            Object v = vehicle;
            if (v instanceof NodeSet set) {
                java.util.Iterator<Node> it = set.iterator();
                v = it.hasNext() ? it.next() : null;
                if (v == null || it.hasNext()) {
                    throw new DslException("downloadMission: expected one vehicle, got " + set);
                }
            }
            if (!(v instanceof MAVLinkNode node)) {
                throw new DslException("downloadMission: " + v + " is not a MAVLink vehicle");
            }
            return node;
        }
    }
}
