package dolphin.sim;

import java.util.Random;

/**
 * Link faults between the simulated vehicles and the ground station, applied to each datagram:
 * loss, duplication, extra delay, and reordering (a random part of the delay, so later datagrams
 * can overtake). Seeded, so a test sees the same faults every run.
 */
public record FaultModel(double loss, double duplication, double delaySeconds, double reorderSeconds, long seed) {

    public static final FaultModel NONE = new FaultModel(0, 0, 0, 0, 1);

    public FaultModel {
        check("loss", loss);
        check("duplication", duplication);
        if (delaySeconds < 0 || reorderSeconds < 0) {
            throw new IllegalArgumentException("delays must not be negative");
        }
    }

    public static FaultModel loss(double p, long seed) {
        return new FaultModel(p, 0, 0, 0, seed);
    }

    public boolean none() {
        return loss == 0 && duplication == 0 && delaySeconds == 0 && reorderSeconds == 0;
    }

    /** The clock delays (seconds) at which copies of one datagram go out: none if lost, two if duplicated. */
    double[] deliveries(Random random) {
        if (random.nextDouble() < loss) {
            return new double[0];
        }
        double first = delaySeconds + random.nextDouble() * reorderSeconds;
        if (random.nextDouble() < duplication) {
            return new double[] {first, delaySeconds + random.nextDouble() * reorderSeconds};
        }
        return new double[] {first};
    }

    private static void check(String what, double p) {
        if (!(p >= 0 && p <= 1)) {
            throw new IllegalArgumentException(what + " must be a probability in [0, 1], got " + p);
        }
    }
}
