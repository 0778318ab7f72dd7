package dolphin.editor;

import java.util.List;
import org.eclipse.lsp4j.CodeAction;
import org.eclipse.lsp4j.Diagnostic;

/** A diagnostic and its quick fixes: code actions that edit the text it was found in. */
record FixableDiagnostic(Diagnostic diagnostic, List<CodeAction> fixes) {
}
