package dolphin.core;

import java.util.List;

/** What a pick or a task requires of a node; unset fields match anything. */
public record NodeFilter(String id, String type, List<String> payload, Area area) {

    public static final NodeFilter ANY = new NodeFilter(null, null, List.of(), null);

    public NodeFilter {
        payload = List.copyOf(payload);
    }

    public boolean matchedBy(Node n) {
        return (id == null || id.equals(n.getId()) || id.equals(n.getName()))
                && (type == null || type.equals(n.getType()))
                && (payload.isEmpty() || n.getPayload().compatibleWith(payload))
                && (area == null || area.contains(n.getPosition()));
    }

    @Override
    public String toString() {
        return "[id " + (id == null ? "*" : id) + ", type " + (type == null ? "*" : type)
                + ", payload " + (payload.isEmpty() ? "*" : payload) + ", area " + (area == null ? "*" : area) + "]";
    }
}
