package dolphin.mavlink.ftp

import dolphin.core.ManualClock
import dolphin.mavlink.LinkTimeouts
import dolphin.mission.transfer.ClockTimers
import java.nio.ByteBuffer
import java.nio.ByteOrder
import java.time.Duration
import java.util.concurrent.CompletableFuture
import java.util.concurrent.CompletionException
import spock.lang.Specification
import spock.lang.Unroll

/**
 * The MAVLink FTP client (FtpClient, FtpSession, FtpRead, FtpWrite) against a FakeFtpServer that
 * answers as ArduPilot does, on a manual clock: no socket, no thread, no real time.
 */
class FtpClientSpec extends Specification {

    static final String MISSION = '@MISSION/mission.dat'

    ManualClock clock = new ManualClock()
    FtpLink link = new FtpLink(clock, { FtpChannel c -> new FtpClient(c, new ClockTimers(clock)) })
    FakeFtpServer server = link.server
    FtpClient client = link.client
    LinkTimeouts timeouts = LinkTimeouts.DEFAULT
    List<List<Long>> progress = []

    static byte[] bytes(int n, int seed = 7) {
        byte[] b = new byte[n]
        new Random(seed).nextBytes(b)
        b
    }

    /** An @MISSION file of {@code count} items: a header, then items of non-zero bytes. */
    static byte[] missionFile(int count) {
        ByteBuffer b = ByteBuffer.allocate(10 + 38 * count).order(ByteOrder.LITTLE_ENDIAN)
        b.putShort((short) 0x763d).putShort((short) 0).putShort((short) 0).putShort((short) 0).putShort((short) count)
        count.times { i -> 38.times { k -> b.put((byte) (1 + (i + k) % 200)) } }
        b.array()
    }

    /** The whole length of an @MISSION file from its first bytes, as MissionFtpFile.length says it. */
    static int missionLength(byte[] head) {
        head.length < 10 ? -1 : 10 + 38 * (ByteBuffer.wrap(head).order(ByteOrder.LITTLE_ENDIAN).getShort(8) & 0xffff)
    }

    def <T> T settle(CompletableFuture<T> f, Duration max = Duration.ofSeconds(60)) {
        long until = clock.nanoTime() + max.toNanos()
        while (!f.isDone() && clock.nanoTime() < until) {
            clock.advance(Duration.ofMillis(10))
        }
        assert f.isDone()
        f.join()
    }

    Throwable failure(CompletableFuture<?> f, Duration max = Duration.ofSeconds(60)) {
        try {
            settle(f, max)
        } catch (CompletionException e) {
            return e.cause
        }
        throw new AssertionError('the transfer succeeded')
    }

    FtpProgress recorder() {
        { long done, long total, int resends -> progress << [done, total, (long) resends] } as FtpProgress
    }

    def "a file is read in one burst: OpenFileRO, BurstReadFile, the short last packet, TerminateSession"() {
        given:
        byte[] file = bytes(1000)
        server.files['/logs/a.bin'] = file

        when:
        FtpFile f = settle(client.read('/logs/a.bin', null, timeouts, recorder()))
        clock.advance(Duration.ofSeconds(1))

        then:
        f.bytes() == file
        f.resends() == 0
        server.requests == [OpenFileRO: 1, BurstReadFile: 1, TerminateSession: 1]
        progress.last() == [1000L, 1000L, 0L]
        progress*.get(0) == [239L, 478L, 717L, 956L, 1000L]
    }

    def "the packets a burst lost are read with ReadFile, at most 4 outstanding"() {
        given:
        byte[] file = bytes(3000)
        server.files['/a'] = file
        server.dropReply = { FtpPayload p, int n -> p.reqOpcode() == FtpPayload.BURST_READ_FILE && p.offset() in [239L, 717L, 956L, 1195L, 1434L, 1673L] }

        when:
        FtpFile f = settle(client.read('/a', null, timeouts, null))

        then:
        f.bytes() == file
        server.requests.ReadFile == 6
        server.mostQueued <= FtpPacing.NETWORK.window()
        server.dropped == 0
    }

    def "a file whose length is a multiple of 239 ends at the burst's EOF NAK, with no ReadFile"() {
        given:
        server.files['/a'] = bytes(239 * 3)

        when:
        FtpFile f = settle(client.read('/a', null, timeouts, null))

        then:
        f.bytes().length == 239 * 3
        server.requests.ReadFile == 0
    }

    def "an @MISSION file ends at the length its header gives, not at its fake 1 MiB, even when the burst's end is lost"() {
        given:
        byte[] file = missionFile(20)     // 770 bytes
        server.files[MISSION] = file
        server.dropReply = { FtpPayload p, int n -> p.reqOpcode() == FtpPayload.BURST_READ_FILE && p.offset() >= 717 || p.opcode() == FtpPayload.NAK }

        when:
        FtpFile f = settle(client.read(MISSION, FtpClientSpec.&missionLength, timeouts, recorder()))

        then:
        f.bytes() == file
        server.requests.ReadFile == 1      // the lost last packet only, never beyond the end
        progress.last() == [770L, 770L, 0L]
    }

    def "lost writes and lost WriteFile ACKs are sent again on their timeouts; TerminateSession closes the file"() {
        given:
        byte[] file = bytes(2000)
        server.dropRequest = { FtpPayload p, int n -> p.opcode() == FtpPayload.WRITE_FILE && p.offset() == 478 && n < 3 }
        server.dropReply = { FtpPayload p, int n -> p.reqOpcode() == FtpPayload.WRITE_FILE && p.offset() == 956 && n < 6 }

        when:
        FtpFile f = settle(client.write('/b', file, timeouts, recorder()))

        then:
        server.files['/b'] == file
        f.resends() == 2
        server.requests.WriteFile == 9 + 1     // 9 blocks, one sent again after its ACK was lost
        server.requests.TerminateSession == 1
        server.mostQueued <= FtpPacing.NETWORK.window()
        progress.last() == [2000L, 2000L, 2L]
    }

    def "the first writes follow the CreateFile at once, not a round trip later"() {
        when:
        FtpFile f = settle(client.write('/b', bytes(2000), timeouts, null))

        then:
        f.bytes() == bytes(2000)
        server.log.findAll { it.startsWith('0.000 > ') }*.split(' ')*.getAt(2) == ['CreateFile'] + ['WriteFile'] * 3
        server.requests.CreateFile == 1
    }

    def "the CreateFile lost: the first write it left without a file sends it again at once, and those writes go again once it is open"() {
        given:
        server.dropRequest = { FtpPayload p, int n -> p.opcode() == FtpPayload.CREATE_FILE && n == 0 }

        when:
        FtpFile f = settle(client.write('/b', bytes(2000), timeouts, recorder()))

        then:
        server.files['/b'] == bytes(2000)
        f.bytes() == bytes(2000)
        server.log.count { it.contains('< NAK to WriteFile FileNotFound') } == 3
        server.requests.WriteFile == 9 + 3
        progress.last()[0..1] == [2000L, 2000L]

        and: 'sent again when the first NAK came (a round trip), not on its timeout (1.5 s before any round trip is measured); once'
        def creates = server.log.findAll { it.contains(' > CreateFile') }*.split(' ')*.getAt(0)*.toDouble()
        creates.size() == 2
        creates[1] < 0.1d
        server.requests.CreateFile == 1
    }

    def "a radio heard during a write: the writes after it carry the radio's 96 bytes, and the file arrives whole"() {
        when:
        def f = client.write('/b', bytes(5000), timeouts, null)
        clock.advance(Duration.ofMillis(60))
        link.pacing = FtpPacing.RADIO
        settle(f)

        then:
        server.files['/b'] == bytes(5000)
        def sizes = server.log.findAll { it.contains(' > WriteFile') }.collect { (it =~ / size (\d+)/)[0][1] as int }
        sizes.first() == 239
        sizes.last() <= 96
        sizes.count { it == 96 } >= 10
    }

    def "the CreateFile's ACK lost: a write's ACK proves the file open, and the CreateFile is not sent again (ArduPilot would refuse it)"() {
        given:
        server.dropReply = { FtpPayload p, int n -> p.reqOpcode() == FtpPayload.CREATE_FILE && n == 0 }

        when:
        FtpFile f = settle(client.write('/b', bytes(2000), timeouts, null))
        clock.advance(Duration.ofSeconds(5))

        then:
        server.files['/b'] == bytes(2000)
        f.resends() == 0
        server.requests.CreateFile == 1
        !server.log.any { it.contains('NAK') }
    }

    def "a checked write asks for the CRC right behind the TerminateSession: the vehicle's CRC of the closed file, no round trip of its own"() {
        when:
        CheckedFile f = settle(client.writeChecked('/b', bytes(2000), timeouts, null))

        then:
        f.file().bytes() == bytes(2000)
        f.vehicleCrc().asLong == FileCrc32.of(bytes(2000))
        def sent = server.log.findAll { it.contains(' > ') }
        sent[-2].contains('TerminateSession') && sent[-1].contains('CalcFileCRC32')
        sent[-2].split(' ')[0] == sent[-1].split(' ')[0]
        server.requests.CalcFileCRC32 == 1
    }

    @Unroll
    def "a checked write whose #lost was lost: the CRC that came before the close is not taken, and is asked again after it"() {
        given: 'the vehicle held another file there before'
        server.files['/b'] = bytes(500, 3)
        server.dropRequest = { FtpPayload p, int n -> lost == 'TerminateSession' && p.opcode() == FtpPayload.TERMINATE_SESSION && n == 0 }
        server.dropReply = { FtpPayload p, int n -> lost == "TerminateSession's ACK" && p.reqOpcode() == FtpPayload.TERMINATE_SESSION && n == 0 }

        when:
        CheckedFile f = settle(client.writeChecked('/b', bytes(2000), timeouts, null))

        then:
        server.files['/b'] == bytes(2000)
        f.vehicleCrc().asLong == FileCrc32.of(bytes(2000))
        server.requests.CalcFileCRC32 == 2
        server.requests.TerminateSession == (lost == 'TerminateSession' ? 1 : 2)

        where:
        lost << ['TerminateSession', "TerminateSession's ACK"]
    }

    def "a checked write refused when closed fails with the vehicle's verdict; the CRC is asked no more"() {
        given:
        byte[] file = missionFile(10)
        file[10 + 38 * 3..<10 + 38 * 4].eachWithIndex { b, i -> file[10 + 38 * 3 + i] = 0 }
        server.dropReply = { FtpPayload p, int n -> p.reqOpcode() == FtpPayload.CALC_FILE_CRC32 }

        when:
        Throwable e = failure(client.writeChecked(MISSION, file, timeouts, null))
        clock.advance(Duration.ofSeconds(20))

        then:
        ((FtpException) e).refusedAtClose()
        server.requests.CalcFileCRC32 == 1
    }

    def "a vehicle without CalcFileCRC32: the checked write succeeds without a CRC"() {
        given:
        server.refuseCrc = true

        when:
        CheckedFile f = settle(client.writeChecked('/b', bytes(300), timeouts, null))

        then:
        server.files['/b'] == bytes(300)
        !f.vehicleCrc().present
    }

    @Unroll
    def "our radio's buffer #free% free: at most #most writes outstanding"() {
        given:
        link.radioBufferFree = free

        when:
        settle(client.write('/b', bytes(2000), timeouts, recorder()))

        then:
        server.files['/b'] == bytes(2000)
        server.mostQueued == most

        where:
        free | most
        -1   | FtpPacing.NETWORK.window()
        80   | FtpPacing.NETWORK.window()
        50   | FtpPacing.NETWORK.window()
        35   | 2
        20   | 2
        10   | 1
    }

    def "two vehicles behind one radio share its window: eight requests in flight, and one more, the second's first; both files written"() {
        given:
        FtpLink other = new FtpLink(clock, { FtpChannel c -> new FtpClient(c, new ClockTimers(clock)) })
        [link, other].each { it.pacing = FtpPacing.RADIO; it.linkRequests = link.linkRequests }
        int most = 0

        when:
        def one = link.client.write('/a', bytes(2000), timeouts, null)
        def two = other.client.write('/b', bytes(1500), timeouts, null)
        for (int i = 0; i < 6000 && !(one.done && two.done); i++) {
            clock.advance(Duration.ofMillis(10))
            most = Math.max(most, link.linkRequests.inFlight())
        }

        then:
        one.get().bytes() == bytes(2000)
        two.get().bytes() == bytes(1500)
        link.server.files['/a'] == bytes(2000)
        other.server.files['/b'] == bytes(1500)
        most == FtpPacing.RADIO.linkWindow() + 1
        link.linkRequests.inFlight() == 0
    }

    def "a transfer always has one request in flight, though the others fill the radio's window"() {
        given:
        link.pacing = FtpPacing.RADIO
        link.linkRequests.add(FtpPacing.RADIO.linkWindow())

        when:
        FtpFile f = settle(client.write('/b', bytes(500), timeouts, recorder()))

        then:
        f.bytes() == bytes(500)
        server.mostQueued == 1
    }

    def "a missing file: the NAK names the file, the operation and the error"() {
        when:
        Throwable e = failure(client.read('/nothing.txt', null, timeouts, null))

        then:
        e instanceof FtpException
        e.message == 'the vehicle refused /nothing.txt when opening it for reading: FileNotFound'
        ((FtpException) e).answered()
        ((FtpException) e).error() == 10
    }

    def "an @MISSION file with an item never written is refused when closed: FailErrno, errno 22 (EINVAL)"() {
        given: 'item 3 all zeros, as if its write never arrived'
        byte[] file = missionFile(10)
        file[10 + 38 * 3..<10 + 38 * 4].eachWithIndex { b, i -> file[10 + 38 * 3 + i] = 0 }

        when:
        Throwable e = failure(client.write(MISSION, file, timeouts, null))

        then:
        e.message == "the vehicle refused $MISSION when closing it: FailErrno, errno 22 (EINVAL)"
        ((FtpException) e).refusedAtClose()
        ((FtpException) e).errno() == 22
        !server.files.containsKey(MISSION)
    }

    def "no session free (ours left open by lost TerminateSessions): ResetSessions, then the file is opened again"() {
        given:
        server.files['/a'] = bytes(300)
        (20..24).each { server.sessions[it] = [path: '/a', mode: 'read'] }

        when:
        FtpFile f = settle(client.read('/a', null, timeouts, null))

        then:
        f.bytes().length == 300
        server.requests.ResetSessions == 1
        server.requests.OpenFileRO == 2
    }

    def "every @MISSION file held by sessions of ours left open (lost TerminateSessions): ENFILE, ResetSessions, then the file is created again"() {
        given: 'four read-backs whose TerminateSession was lost: ArduPilot closes them only after 20 s without a reply'
        (20..23).each { server.sessions[it] = [path: MISSION, mode: 'read'] }
        byte[] file = missionFile(5)

        when:
        settle(client.write(MISSION, file, timeouts, null))

        then:
        server.files[MISSION] == file
        server.log.any { it.contains('FailErrno') && it.contains('CreateFile') }
        server.requests.ResetSessions == 1
        server.requests.CreateFile == 2
    }

    def "a vehicle without FTP: no answer, the read gives up after 10 s without progress, backing off"() {
        given:
        server.silent = true
        def f = client.read(MISSION, null, timeouts, null)
        double end = -1
        f.whenComplete { r, e -> end = clock.seconds() }

        when:
        Throwable e = failure(f)

        then:
        e.message == "no MAVLink FTP answer from the vehicle when opening it for reading ($MISSION, OpenFileRO sent 7 times, nothing new for 10 s)"
        !((FtpException) e).answered()
        end == 10.5
        server.log.findAll { it.contains('OpenFileRO') }.collect { it.split(' ')[0] } ==
                ['0.000', '1.500', '3.000', '4.500', '6.000', '7.500', '9.000']
        server.log.last().contains('TerminateSession')
    }

    def "clean replies feed the round trip (Karn): a request sent again gives no sample"() {
        given:
        server.files['/a'] = bytes(100)
        server.dropReply = { FtpPayload p, int n -> p.reqOpcode() == FtpPayload.OPEN_FILE_RO && n == 0 }

        when:
        settle(client.read('/a', null, timeouts, null))

        then: 'only the burst was answered after one send: 20 ms each way and 1 ms of service'
        link.roundTrip.samples() == 1
        link.roundTrip.smoothedNanos() == 41_000_000
    }

    def "after a sample the resends follow the round trip, not the 1.5 s default"() {
        given:
        server.files['/a'] = bytes(100)
        settle(client.read('/a', null, timeouts, null))
        server.dropRequest = { FtpPayload p, int n -> p.opcode() == FtpPayload.WRITE_FILE && n == 0 }

        when:
        settle(client.write('/b', bytes(100), timeouts, null))

        then: 'the write follows the CreateFile at once, after two clean 41 ms samples (OpenFileRO, the burst): RTO = 41 ms + 4 x 20.5 x 3/4 ms'
        def writes = server.log.findAll { it.contains('> WriteFile') }.collect { it.split(' ')[0] as double }
        writes.size() == 2
        Math.abs(writes[1] - writes[0] - 0.1025) < 0.001
    }

    @Unroll
    def "lossy, duplicating, reordering link (seed #seed): a 5000-byte file is written and read back whole"() {
        given:
        server.random = new Random(seed)
        server.lossUp = 0.2
        server.lossDown = 0.2
        server.duplicate = 0.1
        server.jitter = Duration.ofMillis(40)
        byte[] file = bytes(5000, seed)

        when:
        FtpFile w = settle(client.write('/c', file, timeouts, null))
        FtpFile r = settle(client.read('/c', null, timeouts, null))

        then:
        server.files['/c'] == file
        r.bytes() == file
        w.resends() > 0
        server.dropped == 0

        where:
        seed << [1, 2, 3, 4, 5]
    }
}
