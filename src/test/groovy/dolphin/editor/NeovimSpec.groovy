package dolphin.editor

import dolphin.docs.DocsExamplesSpec
import groovy.json.JsonSlurper
import java.nio.file.Files
import java.nio.file.Path
import java.util.concurrent.TimeUnit
import spock.lang.Requires
import spock.lang.Specification
import spock.lang.Timeout

/**
 * A real editor: Debian's Neovim 0.7.2, headless, configured by the Lua block of docs/editors.md
 * itself (its server command replaced by this JVM's {@code java -cp ... dolphin.cli.Main lsp}), opens
 * a script with a mistake, waits for the diagnostic, asks for completion inside the script's
 * {@code mission { }}, then again inside a typo it writes there ({@code mv|oe}), and writes what it
 * got as JSON; the spec reads it. A second probe asks for the code actions of a diagnostic and
 * applies its quick fix.
 */
@Requires({ Neovim.available() })
@Timeout(180)
class NeovimSpec extends Specification {

    /** How docs/editors.md's Lua names the server; replaced here by this JVM's own command. */
    static final String DOCUMENTED_COMMAND = "'/path/to/dolphin/dolphin', 'lsp'"
    static final long DEADLINE_SECONDS = 60

    static final String SCRIPT = '''homePos = location(40.444233, -7.375234, 820)
survey = mission {
    home homePos

}
v1 = pick { type 'UAV' }
execute
v1: survey
'''

    /** What the test adds after the documented configuration: once the file is open, ask and write the answers. */
    static final String PROBE = '''
    local function complete(line, character)
      local params = { textDocument = { uri = vim.uri_from_bufnr(0) }, position = { line = line, character = character } }
      local responses = vim.lsp.buf_request_sync(0, 'textDocument/completion', params, DEADLINE_MS)
      local items = {}
      for _, response in pairs(responses or {}) do
        local result = response.result or {}
        for _, item in ipairs(result.items or result) do
          local edit = item.textEdit or {}
          table.insert(items, { label = item.label, sortText = item.sortText, filterText = item.filterText,
                                newText = edit.newText, range = edit.range, insertTextFormat = item.insertTextFormat })
        end
      end
      return items
    end
    vim.wait(DEADLINE_MS, function() return #vim.diagnostic.get(0) > 0 end, 50)
    local diagnostics = {}
    for _, d in ipairs(vim.diagnostic.get(0)) do
      table.insert(diagnostics, { lnum = d.lnum, col = d.col, message = d.message })
    end
    local completion = complete(3, 4)
    -- a typo in the mission, completed with the cursor inside it: mv|oe
    vim.api.nvim_buf_set_lines(0, 3, 4, false, { '    mvoe' })
    local typo = complete(3, 6)
    write({ filetype = vim.bo.filetype, diagnostics = diagnostics, completion = completion, typo = typo })
'''

    static final String MISTYPED = 'm = mission {\n    mvoe 50, 0\n}\n'

    /** Once the diagnostic is there: ask for its code actions, apply the first one, wait for the next check. */
    static final String CODE_ACTION_PROBE = '''
    vim.wait(DEADLINE_MS, function() return #vim.diagnostic.get(0) > 0 end, 50)
    local d = vim.diagnostic.get(0)[1]
    local range = { start = { line = d.lnum, character = d.col }, ['end'] = { line = d.end_lnum, character = d.end_col } }
    local params = { textDocument = { uri = vim.uri_from_bufnr(0) }, range = range,
                     context = { diagnostics = { { range = range, message = d.message, severity = 1, source = 'dolphin' } } } }
    local responses = vim.lsp.buf_request_sync(0, 'textDocument/codeAction', params, DEADLINE_MS)
    local titles = {}
    local first = nil
    for _, response in pairs(responses or {}) do
      for _, action in ipairs(response.result or {}) do
        table.insert(titles, action.title)
        first = first or action
      end
    end
    if first then
      vim.lsp.util.apply_workspace_edit(first.edit, 'utf-16')
    end
    vim.wait(DEADLINE_MS, function() return #vim.diagnostic.get(0) == 0 end, 50)
    write({ message = d.message, actions = titles, line = vim.api.nvim_buf_get_lines(0, 1, 2, false)[1],
            after = #vim.diagnostic.get(0) })
'''

    Path dir = Files.createTempDirectory('dolphin-nvim-')

    def cleanup() {
        dir.toFile().deleteDir()
    }

    /** The Lua block of docs/editors.md, the one a user copies. */
    static String documentedConfig() {
        def blocks = DocsExamplesSpec.blocks().findAll { it.kind == 'lua' }
        assert blocks.size() == 1 && blocks[0].doc.endsWith('editors.md'): 'docs/editors.md holds the one Neovim configuration'
        blocks[0].text
    }

    def "Neovim with the documented configuration shows the script's diagnostic and completes the mission commands, move first at mv|oe"() {
        given: 'the documented configuration, the server started as this JVM starts it'
        assert documentedConfig().count(DOCUMENTED_COMMAND) == 1

        when: 'Neovim opens the script, headless, without any user configuration'
        Map got = neovim(PROBE, 'survey.dolphin', SCRIPT)

        then:
        got.error == null

        and: 'the file has the dolphin file type, and the diagnostic of dolphin check on line 7 (0-based 6)'
        got.filetype == 'dolphin'
        got.diagnostics.size() == 1
        got.diagnostics[0].lnum == 6
        got.diagnostics[0].col == 0
        got.diagnostics[0].message.startsWith("'execute' stands alone on its line")

        and: 'completion inside mission { }: the mission commands, first'
        List<Map> items = (got.completion as List<Map>).sort { it.sortText }
        items*.label.containsAll(['goPos', 'takeOff', 'returnHomeAndLand', 'surveyArea'])
        items*.label.indexOf('goPos') < items*.label.indexOf('pick')
        items*.label.contains('homePos')

        and: 'at mv|oe, after the line is changed to mvoe: the move words first, replacing mvoe whole with the word alone (Neovim 0.7 takes no snippets)'
        List<Map> typo = (got.typo as List<Map>).sort { it.sortText }
        typo*.label.take(CompletionSpec.MISSION_MOVE_WORDS.size()) == CompletionSpec.MISSION_MOVE_WORDS
        typo[0].newText == 'move'
        typo[0].filterText == 'move'
        typo[0].insertTextFormat == null
        typo.every { it.range == [start: [line: 3, character: 4], end: [line: 3, character: 8]] }
    }

    def "Neovim gets the quick fix of a 'did you mean' as a code action, and applying it clears the diagnostic"() {
        when:
        Map got = neovim(CODE_ACTION_PROBE, 'mission.dolphin', MISTYPED)

        then:
        got.error == null
        got.message == "unknown command 'mvoe' in mission { }; did you mean 'move'?"
        got.actions == ["Change 'mvoe' to 'move'"]
        got.line == '    move 50, 0'
        got.after == 0
    }

    /**
     * A probe's Lua run once Neovim has opened the file, with {@code write(value)} to hand its answers
     * back as JSON; an error is written instead, and Neovim quits either way.
     */
    static String wrapped(String probe) {
        """
local function write(value)
  local f = assert(io.open(RESULT, 'w'))
  f:write(vim.fn.json_encode(value))
  f:close()
end

vim.api.nvim_create_autocmd('VimEnter', { callback = function()
  local ok, err = pcall(function()
${probe}  end)
  if not ok then
    write({ error = tostring(err) })
  end
  vim.cmd('qa!')
end })
"""
    }

    /** Runs the documented configuration with a probe in a headless Neovim on a script; what the probe wrote. */
    Map neovim(String probe, String name, String text) {
        String java = Path.of(System.getProperty('java.home'), 'bin', 'java').toString()
        String command = ["[[${java}]]", "'-cp'", "[[${System.getProperty('java.class.path')}]]", "'dolphin.cli.Main'", "'lsp'"].join(', ')
        Path result = dir.resolve('result.json')
        Path init = dir.resolve('init.lua')
        Files.writeString(init, documentedConfig().replace(DOCUMENTED_COMMAND, command)
                + wrapped(probe).replace('RESULT', "[[${result}]]").replace('DEADLINE_MS', "${DEADLINE_SECONDS * 1000}"))
        Path script = dir.resolve(name)
        Files.writeString(script, text)
        def nvim = new ProcessBuilder(Neovim.EDITOR.path, '--headless', '--clean', '-u', init.toString(), script.toString())
                .directory(dir.toFile()).redirectErrorStream(true).redirectOutput(dir.resolve('nvim.log').toFile())
        ['XDG_CONFIG_HOME', 'XDG_DATA_HOME', 'XDG_STATE_HOME', 'XDG_CACHE_HOME'].each { nvim.environment()[it] = dir.toString() }
        Process p = nvim.start()
        boolean ended = p.waitFor(DEADLINE_SECONDS + 30, TimeUnit.SECONDS)
        if (!ended) {
            p.destroyForcibly()
        }
        assert ended && Files.exists(result): "Neovim wrote no result; its output:\n${Files.readString(dir.resolve('nvim.log'))}"
        new JsonSlurper().parse(result.toFile()) as Map
    }
}
