package dolphin.sim;

import dolphin.core.Position;

/**
 * RTL of a plane or a rover: home at the height it has (a rover on the ground), then holding there
 * as the firmware holds (a plane circles, a rover stands). As a mission item it is over on arrival.
 */
final class ReturnAndHold implements Manoeuvre {

    private final Firmware firmware;
    private final Craft craft;
    private final Position home;
    private final boolean asMissionItem;
    private Manoeuvre hold;

    ReturnAndHold(Firmware firmware, Craft craft, Position home, boolean asMissionItem) {
        this.firmware = firmware;
        this.craft = craft;
        this.home = home;
        this.asMissionItem = asMissionItem;
    }

    @Override
    public boolean step(double dt) {
        if (hold == null) {
            Position over = home.atHeight(craft.position().hae());
            if (!firmware.reach(craft, over, craft.performance().waypointRadius(), 0, dt)) {
                return false;
            }
            hold = firmware.holdAt(craft, over);
            return asMissionItem;
        }
        hold.step(dt);
        return asMissionItem;
    }
}
