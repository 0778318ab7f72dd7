package dolphin.editor

import dolphin.cli.Main
import dolphin.dsl.vocabulary.LanguageWords
import java.nio.file.Files
import java.nio.file.Path
import spock.lang.Shared
import spock.lang.Specification

/** The GDSL file in the repository and in the jar is the one the vocabulary makes now. */
class GdslFileSpec extends Specification {

    static final String REGENERATE = './dolphin words --gdsl > docs/dolphin.gdsl && cp docs/dolphin.gdsl src/main/resources/dolphin/dolphin.gdsl'

    @Shared
    String printed = wordsGdsl()

    static String wordsGdsl() {
        def out = new StringWriter()
        int code = Main.commandLine(new PrintWriter(out), new PrintWriter(new StringWriter())).execute('words', '--gdsl')
        assert code == 0
        out.toString()
    }

    def "dolphin words --gdsl prints the file written from the language's vocabulary"() {
        expect:
        printed == GdslFile.of(LanguageWords.vocabulary())
        printed.startsWith('// Dolphin\'s words for IntelliJ IDEA')
    }

    def "the committed #path is what the vocabulary makes"() {
        given:
        String committed = Files.readString(Path.of(path))

        expect:
        assert committed == printed, "${path} differs from what the language's words make now: regenerate it with ${REGENERATE}"

        where:
        path << ['docs/dolphin.gdsl', 'src/main/resources/dolphin/dolphin.gdsl']
    }

    def "the jar holds the file where IntelliJ finds it on a library's classpath"() {
        given:
        URL resource = GdslFile.classLoader.getResource(GdslFile.RESOURCE)

        expect:
        resource != null
        resource.text == printed
        GdslFile.RESOURCE.endsWith('.gdsl')
    }
}
