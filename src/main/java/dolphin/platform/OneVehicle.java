package dolphin.platform;

import dolphin.core.Node;
import dolphin.core.NodeSet;
import dolphin.dsl.DslException;
import dolphin.dsl.ScriptContext;
import dolphin.mavlink.MAVLinkNode;
import java.util.Iterator;

/** The one MAVLink vehicle a word is about: a vehicle, or a set holding exactly one. */
final class OneVehicle {

    private OneVehicle() {
    }

    static MAVLinkNode of(ScriptContext context, String word, Object vehicle) {
        context.needsVehicle(word, vehicle);
        Object v = vehicle;
        if (v instanceof NodeSet set) {
            Iterator<Node> it = set.iterator();
            v = it.hasNext() ? it.next() : null;
            if (v == null || it.hasNext()) {
                throw new DslException(word + ": expected one vehicle, got " + set);
            }
        }
        if (!(v instanceof MAVLinkNode node)) {
            throw new DslException(word + ": " + v + " is not a MAVLink vehicle");
        }
        return node;
    }
}
