package dolphin.mission.flight

import spock.lang.Specification

/** Where a mission's items go when its family adds some (a QuadPlane's approach waypoints). */
class BoardedSpec extends Specification {

    def "with items added at #added, item #seq is sent as #sent"() {
        expect:
        new Boarded([], added).seqOf(seq) == sent

        where:
        added  | seq || sent
        []     | 5   || 5
        [4]    | 3   || 3
        [4]    | 4   || 5
        [4]    | 9   || 10
        [4, 8] | 6   || 7
        [4, 8] | 7   || 9
        [4, 6] | 4   || 5
        [4, 6] | 5   || 7
    }
}
