package dolphin.editor;

import dolphin.dsl.vocabulary.WordEntry;
import dolphin.dsl.vocabulary.WordScope;

/** A word and the scope it was found in (a {@code move} inside {@code mission { }} is the mission command). */
record ScopedWord(WordEntry entry, WordScope scope) {
}
