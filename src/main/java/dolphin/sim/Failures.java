package dolphin.sim;

import java.util.Optional;
import java.util.function.IntFunction;

/**
 * What a family of simulated vehicles does when things go wrong: its row of {@link FaultTable}.
 *
 * @param motors how many motors it has, numbered from 1 (SITL's frame)
 * @param powerLoss what the loss of motor N does to it; empty: not simulated
 * @param ekfFailsafe its answer to an EKF that lost its position; empty: a GPS loss is not simulated
 * @param takeoverMode the mode a pilot taking over selects unless told another
 * @param internalError the internal error it reports (once a boot, CRITICAL) when its mission starts a
 *        nav item armed, not being a fault at all; empty: none
 */
record Failures(int motors, Optional<IntFunction<Fault>> powerLoss, Optional<EkfFailsafe> ekfFailsafe, int takeoverMode,
                Optional<String> internalError) {
}
