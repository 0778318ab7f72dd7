package dolphin.web;

import dolphin.mavlink.LinkHealth;
import dolphin.mavlink.RadioStatus;
import groovy.json.JsonOutput;

/**
 * What the page shows of a link: its bytes each way, what it lost, and the telemetry radio's latest
 * report. Rounded as shown (rates to 100 B/s, a radio's age to whole seconds once it is old news),
 * so the link is sent again only when what shows changes.
 *
 * @param in bytes per second received, rounded to 100
 * @param out bytes per second sent, likewise
 * @param radio the latest radio report, or null before one
 * @param radioSilence whole seconds since the radio's last report once it is older than
 *                     {@link LinkHealth#RADIO_CURRENT}, else -1
 */
record LinkView(String name, long in, long out, long lost, long badCrcs, RadioStatus radio, long radioSilence) {

    static LinkView of(LinkHealth h) {
        long silence = h.radio() == null || h.radioCurrent() ? -1 : h.radioAge().toSeconds();
        return new LinkView(h.link(), hundreds(h.inBytesPerSecond()), hundreds(h.outBytesPerSecond()), h.framesLost(),
                h.badCrcs(), h.radio(), silence);
    }

    /** The link as JSON (docs/embedding.md, "The live JSON stream"). */
    String json() {
        return "{\"name\":" + JsonOutput.toJson(name) + ",\"in\":" + in + ",\"out\":" + out + ",\"lost\":" + lost
                + ",\"badCrcs\":" + badCrcs + ",\"radio\":" + radioJson() + "}";
    }

    private String radioJson() {
        if (radio == null) {
            return "null";
        }
        return "{\"rssi\":" + radio.rssi() + ",\"remrssi\":" + radio.remrssi() + ",\"noise\":" + radio.noise()
                + ",\"remnoise\":" + radio.remnoise() + ",\"rssiDbm\":" + dbm(radio.rssiDbm())
                + ",\"remrssiDbm\":" + dbm(radio.remrssiDbm()) + ",\"noiseDbm\":" + dbm(radio.noiseDbm())
                + ",\"remnoiseDbm\":" + dbm(radio.remnoiseDbm())
                + ",\"rxerrors\":" + radio.rxerrors() + ",\"fixed\":" + radio.fixed() + ",\"txbuf\":" + radio.txbuf()
                + ",\"silence\":" + (radioSilence < 0 ? "null" : String.valueOf(radioSilence)) + "}";
    }

    private static long hundreds(double bytesPerSecond) {
        return Math.round(bytesPerSecond / 100) * 100;
    }

    private static String dbm(double value) {
        return Double.isNaN(value) ? "null" : String.valueOf(Math.round(value));
    }
}
