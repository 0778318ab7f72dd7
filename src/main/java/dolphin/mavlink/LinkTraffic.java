package dolphin.mavlink;

import dolphin.mavlink.codec.DropCounters;

/**
 * What one link carries, counted as it goes: bytes each way, frames lost and dropped, and the
 * telemetry radio's latest report. The communications thread writes it; any thread takes a
 * {@link LinkHealth} of it.
 */
final class LinkTraffic {

    private final String link;
    private final DropCounters drops;
    private final ByteRate in;
    private final ByteRate out;
    private final SequenceGaps gaps = new SequenceGaps();
    private RadioStatus radio;

    /** @param drops the counters of this link's frame reader */
    LinkTraffic(String link, DropCounters drops, long nowNanos) {
        this.link = link;
        this.drops = drops;
        this.in = new ByteRate(nowNanos);
        this.out = new ByteRate(nowNanos);
    }

    synchronized void received(long nowNanos, int bytes) {
        in.add(nowNanos, bytes);
    }

    synchronized void sent(long nowNanos, int bytes) {
        out.add(nowNanos, bytes);
    }

    synchronized void frame(int sysid, int compid, int seq) {
        gaps.frame(sysid, compid, seq);
    }

    synchronized void radio(RadioStatus report) {
        radio = report;
    }

    /** Whether a radio ever reported on the link, without the rates a whole snapshot computes. */
    synchronized boolean radioHeard() {
        return radio != null;
    }

    synchronized LinkHealth health(long nowNanos) {
        return new LinkHealth(link, in.perSecond(nowNanos), out.perSecond(nowNanos), in.total(), out.total(), gaps.lost(),
                drops.get(DropCounters.Reason.BAD_CRC), drops.frames(), radio, radio == null ? null : radio.age(nowNanos));
    }
}
