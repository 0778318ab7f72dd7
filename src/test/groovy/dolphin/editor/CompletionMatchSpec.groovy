package dolphin.editor

import spock.lang.Specification

/** How a name matches the word being typed: its beginning, or its letters in order from its start or a hump; case aside. */
class CompletionMatchSpec extends Specification {

    def "'#typed' and #name: #expected"() {
        expect:
        CompletionMatch.of(typed, name) == expected

        where:
        typed  | name                | expected
        ''     | 'move'              | CompletionMatch.PREFIX
        'mo'   | 'move'              | CompletionMatch.PREFIX
        'MO'   | 'move'              | CompletionMatch.PREFIX
        'move' | 'moveFromHome'      | CompletionMatch.PREFIX
        'mv'   | 'move'              | CompletionMatch.SUBSEQUENCE
        'mv'   | 'moveFromHome'      | CompletionMatch.SUBSEQUENCE
        'mfh'  | 'moveFromHome'      | CompletionMatch.SUBSEQUENCE
        'rhl'  | 'returnHomeAndLand' | CompletionMatch.SUBSEQUENCE
        'hl'   | 'returnHomeAndLand' | CompletionMatch.SUBSEQUENCE
        'land' | 'returnHomeAndLand' | CompletionMatch.SUBSEQUENCE
        'p'    | 'home_pos'          | CompletionMatch.SUBSEQUENCE
        'hh'   | 'goHomeHold'        | CompletionMatch.SUBSEQUENCE
        'mv'   | 'maxDepth'          | null
        'ome'  | 'moveFromHome'      | null
        'vm'   | 'move'              | null
        'ov'   | 'move'              | null
        'mvoe' | 'move'              | null
        'moves'| 'move'              | null
        'o'    | 'HOME'              | null
    }
}
