package dolphin.core;

/**
 * A platform with no vehicles, for work that needs none: checking scripts, listing their words,
 * building their missions ({@code dolphin check}, {@code dolphin mission}, the language server).
 */
public final class VehiclelessPlatform implements Platform {

    private final String name;

    /** @param name what the platform is for, in messages: "dry run", "editor" */
    public VehiclelessPlatform(String name) {
        this.name = name;
    }

    @Override
    public String getName() {
        return name;
    }

    @Override
    public NodeSet getConnectedNodes() {
        return new NodeSet();
    }
}
