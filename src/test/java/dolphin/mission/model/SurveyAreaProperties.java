package dolphin.mission.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dolphin.core.Position;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Assume;
import net.jqwik.api.Combinators;
import net.jqwik.api.Example;
import net.jqwik.api.ForAll;
import net.jqwik.api.From;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.constraints.Size;

/**
 * surveyArea as F-4 and design §5 define it: N = round(W / S) + 1 passes, legs of L + 25 m along
 * +-north alternating, a shift of S along +-east after every pass but the last, then back to base;
 * 2N items numbered consecutively, and the declared count equals the emitted count, in a mission
 * too. Geometry is measured back with Position.displacementTo between the emitted items (degE7).
 */
class SurveyAreaProperties {

    static final int WAYPOINT = 16;
    static final int GLOBAL_INT = 5;
    /** Metres: degE7 rounding of both ends plus the tangent-plane steps over up to 5 km. */
    static final double TOLERANCE = 0.1;

    record Survey(Position base, double length, double width, double spacing, SurveyDirection direction, int start) {
        SurveyArea area() {
            return new SurveyArea(base, length, width, spacing, direction);
        }

        long passes() {
            return Math.round(width / spacing) + 1;
        }
    }

    @Provide
    Arbitrary<Position> bases() {
        return Combinators.combine(
                Arbitraries.doubles().between(-60, 60),
                Arbitraries.doubles().between(-179, 179),
                Arbitraries.doubles().between(-100, 4000)).as(Position::fromDegrees);
    }

    @Provide
    Arbitrary<Survey> surveys() {
        Arbitrary<Double> spacing = Arbitraries.doubles().between(5, 500);
        Arbitrary<Double> lanes = Arbitraries.doubles().between(0, 40);
        return Combinators.combine(bases(), Arbitraries.doubles().between(0, 5000), spacing, lanes,
                        Arbitraries.of(SurveyDirection.class), Arbitraries.integers().between(1, 500))
                .as((base, length, s, ratio, d, start) -> new Survey(base, length, s * ratio, s, d, start));
    }

    @Property(tries = 300)
    void theDeclaredCountIsTheEmittedCountAndSeqsAreConsecutive(@ForAll("surveys") Survey s) {
        SurveyArea area = s.area();
        List<MissionItem> items = area.items(s.start());
        long n = s.passes();

        assertEquals(2 * n, items.size());
        assertEquals(items.size(), area.messageCount());
        assertEquals(n, area.passes());
        for (int i = 0; i < items.size(); i++) {
            assertEquals(s.start() + i, items.get(i).seq());
        }
        assertEquals(items.size(), items.stream().map(MissionItem::seq).distinct().count());
    }

    @Property(tries = 300)
    void everyItemIsAWaypointAtTheBaseHeightAndTheLastIsTheBase(@ForAll("surveys") Survey s) {
        List<MissionItem> items = s.area().items(s.start());
        for (MissionItem i : items) {
            assertEquals(WAYPOINT, i.command());
            assertEquals(GLOBAL_INT, i.frame());
            assertEquals(0f, i.param1());
            assertEquals(25f, i.param2());
            assertEquals(0f, i.param3());
            assertTrue(Float.isNaN(i.param4()));
            assertEquals((float) s.base().hae(), i.z());
        }
        MissionItem last = items.get(items.size() - 1);
        assertEquals(MissionItem.degE7(s.base().latitudeDegrees()), last.x());
        assertEquals(MissionItem.degE7(s.base().longitudeDegrees()), last.y());
    }

    @Property(tries = 300)
    void legsHaveTheRequestedLengthPlusTheOvershootAndAlternate(@ForAll("surveys") Survey s) {
        List<MissionItem> items = s.area().items(s.start());
        double leg = s.length() + 25;
        for (int k = 0; k < s.passes(); k++) {
            Position from = k == 0 ? s.base() : items.get(2 * k - 1).position();
            Position to = items.get(2 * k).position();
            double[] ned = from.displacementTo(to);
            double expectedNorth = s.direction().northSign() * leg * (k % 2 == 0 ? 1 : -1);
            assertEquals(expectedNorth, ned[0], TOLERANCE, "pass " + k + " north");
            assertEquals(0, ned[1], TOLERANCE, "pass " + k + " east");
        }
    }

    @Property(tries = 300)
    void lanesAreSpacedAsAsked(@ForAll("surveys") Survey s) {
        List<MissionItem> items = s.area().items(s.start());
        for (int k = 0; k < s.passes() - 1; k++) {
            double[] ned = items.get(2 * k).position().displacementTo(items.get(2 * k + 1).position());
            assertEquals(0, ned[0], TOLERANCE, "shift " + k + " north");
            assertEquals(s.direction().eastSign() * s.spacing(), ned[1], TOLERANCE, "shift " + k + " east");
        }
    }

    @Property(tries = 300)
    void thePassesCoverTheWidth(@ForAll("surveys") Survey s) {
        List<MissionItem> items = s.area().items(s.start());
        double lateral = (s.passes() - 1) * s.spacing();
        // N - 1 lanes of S cover W to within half a lane (N is rounded)
        assertTrue(Math.abs(lateral - s.width()) <= s.spacing() / 2 + 1e-9, "lanes " + lateral + " for width " + s.width());
        // and the last pass really lies that far east (west) of the base: the lanes are measured at
        // alternating latitudes up to 5 km apart, so allow 0.2 % for the convergence of meridians
        Position lastLeg = items.get(items.size() - 2).position();
        double east = s.base().displacementTo(lastLeg)[1];
        assertEquals(s.direction().eastSign() * lateral, east, 0.002 * lateral + TOLERANCE);
    }

    @Example
    void eachOfTheFourDirectionsStartsAndStepsItsOwnWay() {
        Position base = Position.fromDegrees(41.185781, -8.70606486, 100);
        Map<SurveyDirection, int[]> signs = Map.of(
                SurveyDirection.NORTH_EAST, new int[] {1, 1},
                SurveyDirection.NORTH_WEST, new int[] {1, -1},
                SurveyDirection.SOUTH_EAST, new int[] {-1, 1},
                SurveyDirection.SOUTH_WEST, new int[] {-1, -1});
        for (SurveyDirection d : SurveyDirection.values()) {
            List<MissionItem> items = new SurveyArea(base, 1000, 100, 50, d).items(1);
            double[] firstLeg = base.displacementTo(items.get(0).position());
            double[] firstShift = items.get(0).position().displacementTo(items.get(1).position());
            assertEquals(signs.get(d)[0] * 1025, firstLeg[0], TOLERANCE, d + " first leg");
            assertEquals(signs.get(d)[1] * 50, firstShift[1], TOLERANCE, d + " first shift");
            assertEquals(6, items.size(), d + " items");
        }
        assertEquals(SurveyDirection.NORTH_WEST, SurveyArea.DEFAULT_DIRECTION);
        assertEquals(50, SurveyArea.DEFAULT_SPACING);
    }

    @Property(tries = 200)
    void onlyTheFourNamesAreDirections(@ForAll String name) {
        Assume.that(!Set.of("NORTH_EAST", "NORTH_WEST", "SOUTH_EAST", "SOUTH_WEST").contains(name));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> SurveyDirection.parse(name));
        assertEquals("unknown direction '" + name + "': expected NORTH_EAST, NORTH_WEST, SOUTH_EAST or SOUTH_WEST",
                e.getMessage());
    }

    @Example
    void theFourNamesAreDirections() {
        for (SurveyDirection d : SurveyDirection.values()) {
            assertEquals(d, SurveyDirection.parse(d.name()));
        }
        assertThrows(IllegalArgumentException.class, () -> SurveyDirection.parse("north_east"));
    }

    // ---- in a mission

    @Provide
    Arbitrary<DroneCommand> commands() {
        Position p = Position.fromDegrees(41.185781, -8.70606486, 100);
        return Arbitraries.oneOf(
                Arbitraries.just(new GoToPoint(p)),
                Arbitraries.just(new ChangeSpeed(12, 0)),
                Arbitraries.just(new CameraPoint("capturePhoto", 0, 1)),
                Arbitraries.integers().between(0, 3).map(k -> new JumpToItem(k, 1)),
                Combinators.combine(Arbitraries.doubles().between(0, 2000), Arbitraries.doubles().between(0, 1000),
                                Arbitraries.doubles().between(20, 300), Arbitraries.of(SurveyDirection.class))
                        .as((l, w, s, d) -> new SurveyArea(p, l, w, s, d)));
    }

    @Property(tries = 300)
    void inAMissionTheCountIsTheEmittedCountAndJumpsAreKeyedByTheSeqBeforeThem(
            @ForAll @Size(max = 10) List<@From("commands") DroneCommand> commands) {
        Assume.that(commands.stream().anyMatch(c -> c instanceof MissionPoint));
        Mission m = new Mission("m", null, commands);
        List<MissionItem> items = m.items(Position.fromDegrees(41, -8, 0));

        assertEquals(m.missionPoints(), items.size());
        for (int i = 0; i < items.size(); i++) {
            assertEquals(i, items.get(i).seq());
        }
        // each non-item command is keyed by the seq of the last item emitted before it (0: none yet)
        List<Integer> expectedKeys = new ArrayList<>();
        int last = 0;
        for (DroneCommand c : commands) {
            if (c instanceof MissionPoint p) {
                last += p.items(last + 1).size();
            } else {
                expectedKeys.add(last);
            }
        }
        List<Integer> keys = new ArrayList<>();
        m.nonMissionCommands().forEach((k, cs) -> cs.forEach(c -> keys.add(k)));
        keys.sort(Integer::compare);
        assertEquals(expectedKeys, keys);
    }
}
