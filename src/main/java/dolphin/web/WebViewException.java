package dolphin.web;

/** The web view could not start: the message names the address and why. */
public final class WebViewException extends Exception {

    public WebViewException(String message) {
        super(message);
    }
}
