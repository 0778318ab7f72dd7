package dolphin.mavlink.link;

import java.net.InetSocketAddress;

/**
 * A parsed connection string: {@code udpin:HOST:PORT} (listen; learn each vehicle's address from its
 * datagrams), {@code udpout:HOST:PORT} (send to a fixed address), {@code tcp:HOST:PORT} (client) or
 * {@code serial:DEVICE:BAUD}; any of them may end in {@code ?bps=N}, the bits per second the link
 * carries (a radio behind a UDP bridge, say), which the telemetry asked for must fit
 * (docs/radios.md, "Telemetry budget").
 *
 * @param bps the bits per second stated with {@code ?bps=}, 0 when not stated
 */
public record LinkUrl(Transport kind, String host, int port, String device, int baud, int bps, String text) {

    public enum Transport { UDPIN, UDPOUT, TCP, SERIAL }

    public static LinkUrl parse(String text) {
        String whole = text == null ? "" : text.strip();
        int query = whole.indexOf('?');
        int bps = query < 0 ? 0 : bps(whole.substring(query + 1), whole);
        LinkUrl url = parseAddress(query < 0 ? whole : whole.substring(0, query), whole);
        return new LinkUrl(url.kind, url.host, url.port, url.device, url.baud, bps, whole);
    }

    /**
     * The bytes per second the link carries, when known: the stated bits per second, else a serial
     * port's baud rate, each byte ten bits on the wire (8N1); empty for a network link nobody sized.
     */
    public java.util.OptionalDouble bytesPerSecond() {
        int bits = bps > 0 ? bps : kind == Transport.SERIAL ? baud : 0;
        return bits > 0 ? java.util.OptionalDouble.of(bits / 10.0) : java.util.OptionalDouble.empty();
    }

    private static int bps(String query, String text) {
        if (!query.startsWith("bps=")) {
            throw bad(text, "unknown option '" + query + "': the only one is ?bps=BITS_PER_SECOND, e.g. ?bps=57600");
        }
        int bps = number(query.substring(4), text, "bits per second");
        if (bps <= 0) {
            throw bad(text, "the bits per second must be positive, got " + bps);
        }
        return bps;
    }

    private static LinkUrl parseAddress(String t, String text) {
        int colon = t.indexOf(':');
        if (colon < 0) {
            throw bad(text, "expected KIND:ADDRESS, e.g. udpin:0.0.0.0:14559");
        }
        String scheme = t.substring(0, colon).toLowerCase(java.util.Locale.ROOT);
        String rest = t.substring(colon + 1);
        return switch (scheme) {
            case "udpin" -> hostPort(Transport.UDPIN, rest, text);
            case "udpout", "udp" -> hostPort(Transport.UDPOUT, rest, text);
            case "tcp" -> hostPort(Transport.TCP, rest, text);
            case "serial" -> serial(rest, text);
            default -> throw bad(text, "unknown link kind '" + scheme + "': expected udpin, udpout, tcp or serial");
        };
    }

    public InetSocketAddress address() {
        return new InetSocketAddress(host, port);
    }

    private static LinkUrl hostPort(Transport kind, String rest, String text) {
        int colon = rest.lastIndexOf(':');
        if (colon <= 0) {
            throw bad(text, "expected HOST:PORT after '" + kind.name().toLowerCase(java.util.Locale.ROOT) + ":'");
        }
        String host = rest.substring(0, colon);
        int port = number(rest.substring(colon + 1), text, "port");
        int lowest = kind == Transport.UDPIN ? 0 : 1;
        if (port < lowest || port > 65535) {
            throw bad(text, "the port must be between " + lowest + " and 65535, got " + port
                    + (kind == Transport.UDPIN ? " (0 listens on any free port)" : ""));
        }
        return new LinkUrl(kind, host, port, null, 0, 0, text);
    }

    private static LinkUrl serial(String rest, String text) {
        int colon = rest.lastIndexOf(':');
        if (colon <= 0) {
            throw bad(text, "expected DEVICE:BAUD after 'serial:', e.g. serial:/dev/ttyUSB0:57600");
        }
        int baud = number(rest.substring(colon + 1), text, "baud rate");
        if (baud <= 0) {
            throw bad(text, "the baud rate must be positive, got " + baud);
        }
        return new LinkUrl(Transport.SERIAL, null, 0, rest.substring(0, colon), baud, 0, text);
    }

    private static int number(String s, String text, String what) {
        try {
            return Integer.parseInt(s);
        } catch (NumberFormatException e) {
            throw bad(text, "the " + what + " must be a number, got '" + s + "'");
        }
    }

    private static IllegalArgumentException bad(String text, String why) {
        return new IllegalArgumentException("bad connection string '" + text + "': " + why);
    }

    @Override
    public String toString() {
        return text;
    }
}
