package dolphin.mavlink;

import com.MAVLink.Messages.MAVLinkMessage;
import dolphin.core.Node;
import dolphin.core.NodeSet;
import dolphin.dsl.DslException;
import dolphin.dsl.DslExtension;
import dolphin.dsl.ScriptContext;
import dolphin.mavlink.codec.MessageTable;
import dolphin.mavlink.dsl.PositionWords;
import java.util.List;
import org.codehaus.groovy.control.customizers.ImportCustomizer;

/**
 * What the MAVLink platform adds to the language: the generated message classes and enums imported
 * into scripts, the words {@code mission { }}, {@code pos { }} and {@code moveDistance { }} (static
 * imports of {@code dolphin.mavlink.dsl.MissionDsl}, so IDEs see them), {@code move(position, { })}
 * ({@link PositionWords}) and {@code sendMessage(vehicles, message)}. Usable without a link, e.g. to
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
    }
}
