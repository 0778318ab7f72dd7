package dolphin.mavlink

import spock.lang.Specification

/** Frames lost on a link, from the gaps in each sender's sequence numbers. */
class SequenceGapsSpec extends Specification {

    static long lost(List<List<Integer>> frames) {
        def gaps = new SequenceGaps()
        frames.each { gaps.frame(it[0], it[1], it[2]) }
        gaps.lost()
    }

    def "#what: #expected lost"() {
        expect:
        lost(frames) == expected

        where:
        what                                               | frames                                                  || expected
        'every frame, across the wrap at 255'              | [253, 254, 255, 0, 1].collect { [1, 1, it] }            || 0
        'two missing, then two across the wrap'            | [250, 251, 254, 1].collect { [1, 1, it] }               || 4
        'two senders each counted on their own'            | [[1, 1, 5], [51, 68, 90], [1, 1, 6], [51, 68, 92]]      || 1
        'a component of the same system counted apart'     | [[1, 1, 5], [1, 100, 7], [1, 1, 6]]                     || 0
        'a duplicate'                                      | [[1, 1, 5], [1, 1, 5], [1, 1, 6]]                       || 0
    }
}
