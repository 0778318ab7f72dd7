package dolphin.docs;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dolphin.dsl.ScriptResult;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The embedding guide's example runs, and the guide shows it as it is. */
class EmbeddingExampleTest {

    @Test
    void exampleRunsAndReportsWhatTheGuideSays() throws Exception {
        List<String> lines = new ArrayList<>();
        ScriptResult result = EmbeddingExample.demo(line -> {
            synchronized (lines) {
                lines.add(line);
            }
        });
        assertEquals(ScriptResult.Outcome.COMPLETED, result.outcome());
        assertTrue(lines.get(0).startsWith("error: editor.dolphin:1:1: 'execute' stands alone on its line"), lines.get(0));
        assertTrue(lines.contains("message: hello from the host"), lines.toString());
        assertTrue(lines.indexOf("message: idle done") > lines.indexOf("message: hello from the host"), lines.toString());
        assertTrue(lines.contains("task COMPLETED: (idle 0.2 s >> action)"), lines.toString());
        assertEquals("answer: 42", lines.get(lines.size() - 1));
    }

    @Test
    void guideContainsTheExampleVerbatim() throws Exception {
        String guide = Files.readString(Path.of("docs/embedding.md"));
        String source = Files.readString(Path.of("src/test/java/dolphin/docs/EmbeddingExample.java"));
        assertTrue(guide.contains(source.strip()), "docs/embedding.md must include EmbeddingExample.java verbatim");
    }
}
