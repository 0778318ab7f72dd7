package dolphin.core;

import java.util.ArrayList;
import java.util.List;

/** A task a platform runs on vehicles (a MAVLink mission, an IMC plan), with its vehicle requirements. */
public abstract class PlatformTask implements Task {

    private final String id;

    protected PlatformTask(String id) {
        this.id = id;
    }

    @Override
    public String getId() {
        return id;
    }

    /** One filter per vehicle needed. */
    public abstract List<NodeFilter> getRequirements();

    @Override
    public String kind() {
        return "platform task";
    }

    @Override
    public abstract PlatformTaskExecutor getExecutor();

    /** For each requirement, the first matching vehicle in {@code available}; all or nothing. */
    @Override
    public boolean allocate(NodeSet available, Allocation allocation) {
        List<Node> chosen = new ArrayList<>();
        for (NodeFilter requirement : getRequirements()) {
            Node match = null;
            for (Node n : available) {
                if (!chosen.contains(n) && requirement.matchedBy(n)) {
                    match = n;
                    break;
                }
            }
            if (match == null) {
                allocation.fail("task '" + id + "' found no vehicle matching " + requirement
                        + " among the free ones " + NodeSet.difference(available, new NodeSet(chosen)));
                return false;
            }
            chosen.add(match);
        }
        chosen.forEach(available::remove);
        allocation.assign(chosen);
        return true;
    }

    @Override
    public String toString() {
        return getId();
    }
}
