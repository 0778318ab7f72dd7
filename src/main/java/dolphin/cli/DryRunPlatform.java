package dolphin.cli;

import dolphin.core.NodeSet;
import dolphin.core.Platform;

/** A platform without vehicles, for work that needs none: checking scripts, building missions (dolphin mission). */
final class DryRunPlatform implements Platform {

    @Override
    public String getName() {
        return "dry run";
    }

    @Override
    public NodeSet getConnectedNodes() {
        return new NodeSet();
    }
}
