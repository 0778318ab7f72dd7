package dolphin.editor;

import dolphin.core.NodeSet;
import dolphin.core.Platform;

/** A platform without vehicles: the editor only checks scripts, it never runs them. */
final class EditorPlatform implements Platform {

    @Override
    public String getName() {
        return "editor";
    }

    @Override
    public NodeSet getConnectedNodes() {
        return new NodeSet();
    }
}
