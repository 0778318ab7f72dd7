package dolphin.sim;

import dolphin.core.Position;

/** A quantity that varies over the ground (smoke, gas, temperature), as a simulated sensor reads it where the vehicle is. */
public sealed interface SimField permits PlumeField, LinearField {

    /** The value at {@code p}; heights do not matter. */
    double valueAt(Position p);
}
