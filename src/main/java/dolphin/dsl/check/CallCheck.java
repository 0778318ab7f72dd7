package dolphin.dsl.check;

import java.util.List;

/**
 * A platform's check of a call to one of its words whose arguments are constants, e.g. that the
 * file {@code missionFromFile 'survey.plan'} names exists.
 */
@FunctionalInterface
public interface CallCheck {

    /**
     * The mistake in the call, or null when there is none or the check does not apply.
     *
     * @param word the word called
     * @param constants its arguments, in order: each a constant's value, or {@link #UNKNOWN}
     */
    String mistake(String word, List<Object> constants);

    /** An argument whose value is known only at run time. */
    Object UNKNOWN = new Object() {
        @Override
        public String toString() {
            return "(unknown)";
        }
    };
}
