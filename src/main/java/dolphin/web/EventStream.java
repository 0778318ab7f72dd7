package dolphin.web;

import com.sun.net.httpserver.HttpExchange;
import com.sun.net.httpserver.HttpHandler;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Function;
import java.util.function.Supplier;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * {@code /events}: the JSON stream as Server-Sent Events (docs/embedding.md): a {@code snapshot},
 * then an {@code update} per frame with what changed since the last one this viewer was sent, and
 * {@code end} when the run is over. Each viewer is served on its own thread; one that reads slowly
 * skips frames, one that goes away ends its thread, and neither touches the run.
 */
final class EventStream implements HttpHandler {

    private static final Logger LOG = LoggerFactory.getLogger(EventStream.class);
    static final int MAX_VIEWERS = 32;
    static final Duration KEEP_ALIVE = Duration.ofSeconds(15);

    private final Broadcast broadcast;
    private final EventLog log;
    /** The snapshot for a new viewer, given the frame it starts from. */
    private final Function<FleetFeed.FeedFrame, String> snapshot;
    /** Members every update carries (the run's script and outcome). */
    private final Supplier<String> always;
    private final AtomicInteger viewers = new AtomicInteger();

    EventStream(Broadcast broadcast, EventLog log, Function<FleetFeed.FeedFrame, String> snapshot, Supplier<String> always) {
        this.broadcast = broadcast;
        this.log = log;
        this.snapshot = snapshot;
        this.always = always;
    }

    int viewers() {
        return viewers.get();
    }

    @Override
    public void handle(HttpExchange ex) throws IOException {
        if (viewers.incrementAndGet() > MAX_VIEWERS) {
            viewers.decrementAndGet();
            Reply.text(ex, 503, "already " + MAX_VIEWERS + " viewers of this run");
            return;
        }
        try (ex; OutputStream out = ex.getResponseBody()) {
            ex.getResponseHeaders().set("Content-Type", "text/event-stream; charset=utf-8");
            ex.getResponseHeaders().set("Cache-Control", "no-store");
            ex.sendResponseHeaders(200, 0);
            stream(out);
        } catch (IOException e) {
            LOG.debug("a viewer went away: {}", e.getMessage());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } finally {
            viewers.decrementAndGet();
        }
    }

    private void stream(OutputStream out) throws IOException, InterruptedException {
        FleetFeed.FeedFrame sent = broadcast.latest();
        long logSeq = log.last();
        send(out, "snapshot", snapshot.apply(sent));
        while (true) {
            boolean ended = broadcast.ended();
            FleetFeed.FeedFrame next = broadcast.awaitAfter(sent.number(), KEEP_ALIVE);
            if (next.number() > sent.number() || log.last() > logSeq) {
                EventLog.Since since = log.since(logSeq);
                send(out, "update", FleetFeed.update(next, sent.number(), since, always.get()));
                if (!since.entries().isEmpty()) {
                    logSeq = since.entries().get(since.entries().size() - 1).seq();
                }
                sent = next;
            } else if (!ended && !broadcast.ended()) {
                out.write(": keep-alive\n\n".getBytes(StandardCharsets.UTF_8));
                out.flush();
            }
            if (ended) {
                send(out, "end", "{}");
                return;
            }
        }
    }

    /** One event; a line break in the data (none in our JSON) would continue it on another data line. */
    static void send(OutputStream out, String event, String json) throws IOException {
        out.write(("event: " + event + "\ndata: " + json.replace("\n", "\ndata: ") + "\n\n").getBytes(StandardCharsets.UTF_8));
        out.flush();
    }
}
