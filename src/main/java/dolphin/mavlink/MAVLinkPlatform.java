package dolphin.mavlink;

import dolphin.mavlink.codec.MessageTable;
import com.MAVLink.Messages.MAVLinkMessage;
import dolphin.core.Node;
import dolphin.core.NodeSet;
import dolphin.core.Platform;
import dolphin.dsl.DslException;
import dolphin.dsl.DslExtension;
import dolphin.dsl.ScriptContext;
import java.util.List;
import org.codehaus.groovy.control.customizers.ImportCustomizer;

/**
 * MAVLink vehicles for Dolphin scripts: the connected vehicles for pick, the generated message
 * classes imported into scripts, and the word {@code sendMessage(vehicles, message)}.
 */
public final class MAVLinkPlatform implements Platform, DslExtension {

    private final MAVLinkCommunications comms;

    public MAVLinkPlatform(MAVLinkCommunications comms) {
        this.comms = comms;
    }

    public MAVLinkCommunications communications() {
        return comms;
    }

    @Override
    public String getName() {
        return "MAVLink";
    }

    /** Vehicles heard within their connection timeout, by system id. */
    @Override
    public NodeSet getConnectedNodes() {
        return new NodeSet(comms.nodes().stream().filter(Node::isConnected).toList());
    }

    @Override
    public void setTelemetryListener(Runnable onTelemetry) {
        comms.setTelemetryListener(onTelemetry);
    }

    @Override
    public void addImports(ImportCustomizer imports) {
        imports.addStarImports("com.MAVLink.minimal", "com.MAVLink.standard", "com.MAVLink.common",
                "com.MAVLink.ardupilotmega", "com.MAVLink.enums", "com.MAVLink.Messages");
    }

    @Override
    public List<Object> words(ScriptContext context) {
        return List.of(new Words(context));
    }

    @Override
    public void close() {
        comms.close();
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
