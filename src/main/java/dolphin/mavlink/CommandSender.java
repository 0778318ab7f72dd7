package dolphin.mavlink;

import com.MAVLink.common.msg_command_ack;
import com.MAVLink.common.msg_command_long;
import com.MAVLink.enums.MAV_RESULT;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.HashMap;
import java.util.Iterator;
import java.util.Map;
import java.util.concurrent.CompletableFuture;

/**
 * Sends COMMAND_LONGs and waits for their COMMAND_ACK, resending (with the confirmation field
 * counting up) after a timeout. An ACK names only the command, so commands with the same id to the
 * same vehicle are queued and sent one at a time. Runs on the communications thread only.
 */
final class CommandSender {

    interface Transmit {
        void send(MAVLinkNode node, msg_command_long command);
    }

    private static final class Pending {
        final MAVLinkNode node;
        final msg_command_long command;
        final CompletableFuture<CommandResult> result = new CompletableFuture<>();
        int attempts;
        long deadline;
        long sentAt;
        boolean inProgress;

        Pending(MAVLinkNode node, msg_command_long command) {
            this.node = node;
            this.command = command;
        }
    }

    private final Transmit transmit;
    private final long timeoutNanos;
    private final int maxAttempts;
    private final Map<String, Deque<Pending>> queues = new HashMap<>();

    CommandSender(Transmit transmit, long timeoutNanos, int maxAttempts) {
        this.transmit = transmit;
        this.timeoutNanos = timeoutNanos;
        this.maxAttempts = maxAttempts;
    }

    CompletableFuture<CommandResult> submit(MAVLinkNode node, msg_command_long command, long now) {
        Pending p = new Pending(node, command);
        Deque<Pending> q = queues.computeIfAbsent(key(node, command.command), k -> new ArrayDeque<>());
        q.add(p);
        if (q.size() == 1) {
            send(p, now);
        }
        return p.result;
    }

    void onAck(MAVLinkNode node, msg_command_ack ack, long now) {
        String k = key(node, ack.command);
        Deque<Pending> q = queues.get(k);
        if (q == null || q.isEmpty()) {
            return;
        }
        Pending head = q.peek();
        if (ack.result == MAV_RESULT.MAV_RESULT_IN_PROGRESS) {
            head.deadline = now + timeoutNanos;
            head.inProgress = true;
            return;
        }
        q.poll();
        if (head.attempts == 1 && !head.inProgress) {
            node.roundTrip().sample(now - head.sentAt);      // sent once, answered at once: a clean sample (Karn)
        }
        head.result.complete(new CommandResult(ack.command, ack.result, head.attempts));
        next(k, q, now);
    }

    /** Resends what timed out, and gives up after the last attempt. */
    void tick(long now) {
        for (Iterator<Map.Entry<String, Deque<Pending>>> it = queues.entrySet().iterator(); it.hasNext(); ) {
            Map.Entry<String, Deque<Pending>> e = it.next();
            Deque<Pending> q = e.getValue();
            Pending head = q.peek();
            if (head == null) {
                it.remove();
                continue;
            }
            if (now < head.deadline) {
                continue;
            }
            if (head.attempts >= maxAttempts || !head.node.isConnected()) {
                q.poll();
                head.result.complete(new CommandResult(head.command.command, CommandResult.NO_ACK, head.attempts));
                if (q.isEmpty()) {
                    it.remove();
                } else {
                    send(q.peek(), now);
                }
            } else {
                send(head, now);
            }
        }
    }

    private void next(String k, Deque<Pending> q, long now) {
        if (q.isEmpty()) {
            queues.remove(k);
        } else {
            send(q.peek(), now);
        }
    }

    private void send(Pending p, long now) {
        p.command.confirmation = (short) Math.min(255, p.attempts);
        p.attempts++;
        p.deadline = now + timeoutNanos;
        p.sentAt = now;
        transmit.send(p.node, p.command);
    }

    private static String key(MAVLinkNode node, int command) {
        return node.getId() + "/" + command;
    }
}
