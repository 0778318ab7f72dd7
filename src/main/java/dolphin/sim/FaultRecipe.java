package dolphin.sim;

/** How to make a fault from what the user gave, once the vehicle's firmware is known ({@link FaultKind}). */
@FunctionalInterface
interface FaultRecipe {

    /** The fault on a vehicle of {@code firmware}; IllegalArgumentException, saying why, when it cannot have it. */
    Fault make(Firmware firmware);
}
