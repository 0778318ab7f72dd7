package dolphin.mavlink;

import dolphin.mavlink.codec.MessageTable;
import com.MAVLink.Messages.MAVLinkMessage;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.BiConsumer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Routes decoded messages to consumers by their exact message class. A consumer
 * that throws is logged and the others still run: input never kills the communications thread.
 */
public final class MessageHandler {

    private static final Logger LOG = LoggerFactory.getLogger(MessageHandler.class);

    private final Map<Class<?>, List<BiConsumer<MAVLinkNode, MAVLinkMessage>>> routes = new ConcurrentHashMap<>();

    @SuppressWarnings("unchecked")
    public <M extends MAVLinkMessage> void on(Class<M> type, BiConsumer<MAVLinkNode, ? super M> consumer) {
        routes.computeIfAbsent(type, t -> new CopyOnWriteArrayList<>()).add((BiConsumer<MAVLinkNode, MAVLinkMessage>) consumer);
    }

    /** Returns the number of consumers that received the message. */
    public int dispatch(MAVLinkNode node, MAVLinkMessage message) {
        List<BiConsumer<MAVLinkNode, MAVLinkMessage>> consumers = routes.get(message.getClass());
        if (consumers == null) {
            return 0;
        }
        for (BiConsumer<MAVLinkNode, MAVLinkMessage> c : consumers) {
            try {
                c.accept(node, message);
            } catch (RuntimeException e) {
                LOG.warn("handling {} from vehicle {} failed", MessageTable.get().name(message.msgid), node.getId(), e);
            }
        }
        return consumers.size();
    }
}
