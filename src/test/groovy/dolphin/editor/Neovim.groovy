package dolphin.editor

/** Debian's Neovim (apt: neovim; .ci/run installs it), for the real-client test. */
final class Neovim {
    static final File EDITOR = new File('/usr/bin/nvim')

    static boolean available() {
        EDITOR.canExecute()
    }
}
