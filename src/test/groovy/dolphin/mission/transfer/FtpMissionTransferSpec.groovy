package dolphin.mission.transfer

import com.MAVLink.Messages.MAVLinkMessage
import com.MAVLink.common.msg_file_transfer_protocol
import com.MAVLink.enums.MAV_MISSION_RESULT
import dolphin.core.ManualClock
import dolphin.core.Position
import dolphin.mavlink.LinkTimeouts
import dolphin.mavlink.ftp.FakeFtpServer
import dolphin.mission.model.MissionItem
import dolphin.mission.model.MissionType
import java.nio.ByteBuffer
import java.nio.ByteOrder
import java.time.Duration
import java.util.concurrent.CompletableFuture
import spock.lang.Specification
import spock.lang.Unroll

import static dolphin.mission.transfer.MissionTransferSpec.fence
import static dolphin.mission.transfer.MissionTransferSpec.intended

/**
 * Mission transfers over MAVLink FTP and the choice of path (MissionTransfers, FtpMissionUpload,
 * FtpMissionDownload) on a manual clock, with no socket: the vehicle is a ScriptedMissionVehicle
 * for the mission protocol and a FakeFtpServer for FTP on the same RecordingChannel.
 */
class FtpMissionTransferSpec extends Specification {

    static final String MISSION = '@MISSION/mission.dat'
    static final String REFUSED = "upload to vehicle 2 failed: over FTP: the vehicle refused $MISSION when closing it:" +
            ' FailErrno, errno 22 (EINVAL): ArduPilot could not read a complete list from it'

    ManualClock clock = new ManualClock()
    RecordingChannel channel = new RecordingChannel(clock)
    ScriptedMissionVehicle vehicle = new ScriptedMissionVehicle(clock, channel)
    FakeFtpServer server = new FakeFtpServer(clock, { MAVLinkMessage m -> channel.receive(m) })
    MissionTransfers transfers = new MissionTransfers(channel, new ClockTimers(clock), { MissionTransferConfig.DEFAULT })
    List<TransferStatus> statuses = []

    def setup() {
        channel.transfers = transfers
        Closure items = channel.receiver
        channel.receiver = { MAVLinkMessage m -> m instanceof msg_file_transfer_protocol ? server.receive(m) : items(m) }
        channel.offersFtp = Optional.of(true)
    }

    static MissionTransferConfig on(TransferPath path) {
        new MissionTransferConfig(LinkTimeouts.DEFAULT, path)
    }

    TransferResult settle(CompletableFuture<TransferResult> f) {
        for (int i = 0; i < 6000 && !f.isDone(); i++) {
            clock.advance(Duration.ofMillis(10))
        }
        assert f.isDone()
        f.join()
    }

    CompletableFuture<TransferResult> upload(TransferPath path, MissionType type = MissionType.MISSION, List<MissionItem> items = intended()) {
        transfers.upload().upload(type, items, on(path), { TransferStatus s -> statuses << s })
    }

    int ftpMessages() {
        channel.sent.count { it.message instanceof msg_file_transfer_protocol }
    }

    int missionMessages() {
        channel.sent.count { !(it.message instanceof msg_file_transfer_protocol) }
    }

    /** The first message of the mission protocol sent: when the transfer went item by item. */
    def firstItemMessage() {
        channel.sent.find { !(it.message instanceof msg_file_transfer_protocol) }
    }

    def "FILE_TRANSFER_PROTOCOL is one of the messages the mission layer routes to the transfers"() {
        expect:
        MissionTransfers.MESSAGES.contains(msg_file_transfer_protocol)
    }

    def "AUTO, the vehicle offers FTP: the mission is written as one file, read back and found equal"() {
        when:
        TransferResult r = settle(upload(TransferPath.AUTO))

        then:
        r.success()
        r.verified()
        r.note() == 'over FTP'
        r.items() == intended()
        MissionFtpFile.decode(server.files[MISSION]).items() == intended()
        missionMessages() == 0
        server.requests.CreateFile == 1
        server.requests.BurstReadFile == 1
        statuses.every { it.path() == TransferPath.FTP && it.upload() && it.unit() == 'bytes' }
        statuses.last().done() == 2 * (10 + 5 * 38)
        statuses.last().total() == 2 * (10 + 5 * 38)
        statuses.last().text() == 'uploading over FTP: 400 of 400 bytes'
    }

    def "a fence goes to fence.dat"() {
        when:
        TransferResult r = settle(upload(TransferPath.FTP, MissionType.FENCE, fence()))

        then:
        r.verified()
        MissionFtpFile.decode(server.files['@MISSION/fence.dat']).type() == MissionType.FENCE
    }

    def "a download over FTP reads the file to the length its header gives"() {
        given:
        server.files[MISSION] = MissionFtpFile.encode(MissionType.MISSION, intended())

        when:
        TransferResult r = settle(transfers.download().download(MissionType.MISSION, on(TransferPath.AUTO),
                { TransferStatus s -> statuses << s }))

        then:
        r.success()
        r.note() == 'over FTP'
        r.items() == intended()
        statuses.last().text() == 'downloading over FTP: 200 of 200 bytes'
        missionMessages() == 0
    }

    def "the list refused when the file is closed: AUTO uploads it item by item instead"() {
        given:
        server.refuseList = { String path, byte[] b -> true }

        when:
        TransferResult r = settle(upload(TransferPath.AUTO))

        then:
        r.success()
        !r.verified()
        r.note() == "item by item, as FTP failed (the vehicle refused $MISSION when closing it: FailErrno, errno 22 (EINVAL):" +
                ' ArduPilot could not read a complete list from it)'
        vehicle.stored == intended()
        statuses*.path().unique() == [TransferPath.FTP, TransferPath.ITEMS]
    }

    def "the list refused over FTP, then item by item: the error names the refused item"() {
        given:
        server.refuseList = { String path, byte[] b -> true }
        vehicle.faults = ['errorAck'] as Set
        vehicle.faultSeq = 2
        vehicle.errorAck = MAV_MISSION_RESULT.MAV_MISSION_INVALID_PARAM7

        when:
        TransferResult r = settle(upload(TransferPath.AUTO))

        then:
        !r.success()
        r.error().startsWith('upload to vehicle 2 failed: item 2 (NAV_WAYPOINT): MAV_MISSION_INVALID_PARAM7')
    }

    def "FTP forced: the refused file fails the upload with the vehicle's verdict"() {
        given:
        server.refuseList = { String path, byte[] b -> true }

        when:
        TransferResult r = settle(upload(TransferPath.FTP))

        then:
        !r.success()
        r.error() == REFUSED
        missionMessages() == 0
    }

    def "a list the vehicle kept otherwise than sent: the read-back finds it; AUTO falls back, FTP fails"() {
        given: 'the vehicle keeps item 2 at 25 m'
        server.keep = { String path, byte[] b ->
            byte[] k = b.clone()
            ByteBuffer.wrap(k).order(ByteOrder.LITTLE_ENDIAN).putFloat(10 + 2 * 38 + 24, 25f)
            k
        }

        when:
        TransferResult auto = settle(upload(TransferPath.AUTO))
        TransferResult forced = settle(upload(TransferPath.FTP))

        then:
        auto.success()
        !auto.verified()
        vehicle.stored == intended()
        !forced.success()
        forced.error() == "upload to vehicle 2 failed: over FTP: $MISSION read back differs from what was sent:" +
                ' item 2 (NAV_WAYPOINT): z sent 102.0, vehicle has 25.0'
    }

    def "a vehicle that says FTP but never answers it: AUTO falls back after 10 s and later goes straight to items"() {
        given:
        server.silent = true

        when:
        TransferResult first = settle(upload(TransferPath.AUTO))
        int asked = ftpMessages()
        TransferResult second = settle(upload(TransferPath.AUTO))

        then:
        first.success()
        second.success()
        asked > 0
        ftpMessages() == asked
        vehicle.stored == intended()
    }

    def "a vehicle remembered as without FTP: a forced FTP upload that succeeds lets AUTO use FTP again"() {
        given:
        server.silent = true
        settle(upload(TransferPath.AUTO))

        when:
        server.silent = false
        TransferResult forced = settle(upload(TransferPath.FTP))
        int asked = ftpMessages()
        TransferResult auto = settle(upload(TransferPath.AUTO))

        then:
        forced.verified()
        auto.verified()
        auto.note() == 'over FTP'
        ftpMessages() > asked
    }

    def "FTP that answered and then fell silent (the read-back lost): AUTO falls back, but the next upload tries FTP again"() {
        given:
        server.dropRequest = { p, int n -> p.opcode() == 4 }     // every OpenFileRO

        when:
        TransferResult first = settle(upload(TransferPath.AUTO))
        int asked = ftpMessages()
        server.dropRequest = { p, int n -> false }
        TransferResult second = settle(upload(TransferPath.AUTO))

        then:
        first.success()
        !first.verified()
        second.verified()
        ftpMessages() > asked
    }

    def "FTP forced on a vehicle that never answers it: a clear error after 10 s"() {
        given:
        server.silent = true

        when:
        TransferResult r = settle(upload(TransferPath.FTP))

        then:
        !r.success()
        r.error() == "upload to vehicle 2 failed: over FTP: no MAVLink FTP answer from the vehicle when creating it ($MISSION," +
                ' CreateFile sent 7 times, nothing new for 10 s)'
        missionMessages() == 0
    }

    @Unroll
    def "the vehicle's FTP capability #offers: AUTO goes #how; FTP forced #forced"() {
        given:
        channel.offersFtp = offers

        when:
        TransferResult auto = settle(upload(TransferPath.AUTO))
        int ftpByAuto = ftpMessages()
        TransferResult ftp = settle(upload(TransferPath.FTP))

        then:
        auto.success()
        (ftpByAuto > 0) == (how == 'over FTP')
        ftp.success() == (forced == 'succeeds')
        ftp.success() || ftp.error() == 'upload to vehicle 2 failed: the vehicle does not offer MAVLink FTP' +
                ' (no MAV_PROTOCOL_CAPABILITY_FTP in its AUTOPILOT_VERSION): transfer it item by item'

        where:
        offers              | how            | forced
        Optional.of(true)   | 'over FTP'     | 'succeeds'
        Optional.of(false)  | 'item by item' | 'fails at once'
        Optional.empty()    | 'over FTP'     | 'succeeds'
    }

    def "AUTO on a vehicle that has not said what it offers: it asks again and tries FTP meanwhile, whose answer proves it"() {
        given: 'the first AUTOPILOT_VERSION was lost, and so is every later one'
        channel.offersFtp = Optional.empty()

        when:
        CompletableFuture<TransferResult> f = upload(TransferPath.AUTO)

        then: 'the ask and the CreateFile go at once'
        channel.asks == 1
        channel.sent.first().time == 0.0d
        channel.sent.first().message instanceof msg_file_transfer_protocol
        server.log.first().startsWith('0.000 > ') && server.log.first().contains('CreateFile')

        when:
        TransferResult r = settle(f)

        then:
        r.verified()
        r.note() == 'over FTP'
        missionMessages() == 0
        channel.offersFtp == Optional.empty()
    }

    def "AUTO on a vehicle that never says what it offers nor answers FTP: item by item after 3 s, saying why, its file closed"() {
        given:
        channel.offersFtp = Optional.empty()
        server.silent = true

        when:
        TransferResult r = settle(upload(TransferPath.AUTO))

        then:
        r.success()
        r.note() == 'item by item: the vehicle has not said whether it offers MAVLink FTP (AUTOPILOT_VERSION asked 1 time)'
        vehicle.stored == intended()
        def firstItem = firstItemMessage()
        firstItem.time >= 3.0d && firstItem.time < 3.1d
        def ftpSent = channel.sent.findAll { it.message instanceof msg_file_transfer_protocol }
        server.log.findAll { it.contains(' > ') }.last().contains('TerminateSession')
        ftpSent.every { it.time <= firstItem.time }

        when: 'the next upload: the vehicle still silent, FTP is tried again (nothing was learnt of it)'
        TransferResult next = settle(upload(TransferPath.AUTO))

        then:
        next.success()
        next.note().startsWith('item by item: the vehicle has not said')
        channel.sent.count { it.message instanceof msg_file_transfer_protocol && it.time > firstItem.time } > 0
    }

    def "AUTO on a vehicle that says it has no FTP while FTP is tried: item by item at once, saying so"() {
        given: 'the ask the transfer sends is answered 0.4 s later; FTP gets no answer'
        channel.offersFtp = Optional.empty()
        channel.answerAsk = { clock.schedule(Duration.ofMillis(400)) { channel.offersFtp = Optional.of(false) } }
        server.silent = true

        when:
        TransferResult r = settle(upload(TransferPath.AUTO))

        then:
        r.success()
        r.note() == 'item by item: the vehicle offers no MAVLink FTP'
        vehicle.stored == intended()
        def firstItem = firstItemMessage()
        firstItem.time >= 0.4d && firstItem.time < 0.5d
    }

    def "AUTO on a vehicle asked in vain more than three times: item by item at once"() {
        given:
        channel.offersFtp = Optional.empty()
        channel.asks = 4

        when:
        TransferResult r = settle(upload(TransferPath.AUTO))

        then:
        r.success()
        channel.sent.first().time == 0.0d
        r.note() == 'item by item: the vehicle has not said whether it offers MAVLink FTP (AUTOPILOT_VERSION asked 4 times)'
        channel.asks == 4
    }

    def "AUTO on a vehicle without FTP says so; the paths a user forced need no word"() {
        given:
        channel.offersFtp = Optional.of(false)

        when:
        TransferResult auto = settle(upload(TransferPath.AUTO))
        TransferResult items = settle(upload(TransferPath.ITEMS))

        then:
        auto.note() == 'item by item: the vehicle offers no MAVLink FTP'
        items.note() == ''
        channel.asks == 0
    }

    /**
     * ArduPilot's storage of a list written: what StoredItems says it keeps, {@code home} as item 0
     * (null: a vehicle whose home is not set); the vehicle reports that home.
     */
    void vehicleStoresAsArduPilot(Position home = MissionTransferSpec.HOME) {
        channel.home = home
        server.keep = { String path, byte[] bytes ->
            MissionFtpFile.Contents c = MissionFtpFile.decode(bytes)
            StoredItems.file(c.type(), c.items(), home, false)
        }
    }

    /** One CalcFileCRC32 checked the upload: nothing was read back over the link. */
    boolean checkedByCrcAlone() {
        server.requests['CalcFileCRC32'] == 1 && server.requests['OpenFileRO'] == 0
    }

    def "the vehicle's CRC of its read-back matches the one predicted: verified with one request, nothing read"() {
        given:
        vehicleStoresAsArduPilot()

        when:
        TransferResult r = settle(upload(TransferPath.FTP))

        then:
        r.verified()
        checkedByCrcAlone()
        statuses.last().done() == statuses.last().total()
    }

    def "a vehicle that has not reported its home is asked for it when the upload begins: the CRC check waits for the answer"() {
        given: 'the home comes 0.6 s after the ask, long after the file is written'
        vehicleStoresAsArduPilot()
        channel.home = null
        channel.answerHome = { clock.schedule(Duration.ofMillis(600)) { channel.home = MissionTransferSpec.HOME } }

        when:
        CompletableFuture<TransferResult> f = upload(TransferPath.FTP)

        then:
        channel.homeAsks == 1

        when:
        double doneAt = -1
        f.thenRun { doneAt = clock.seconds() }
        TransferResult r = settle(f)

        then:
        r.verified()
        channel.homeAsks == 1
        checkedByCrcAlone()
        doneAt >= 0.6d && doneAt < 0.7d
    }

    def "a vehicle whose home is not set sends none: its CRC is that of item 0 all zeros, as ArduPilot reads it, and no home is waited for"() {
        given:
        vehicleStoresAsArduPilot(null)

        when:
        CompletableFuture<TransferResult> f = upload(TransferPath.FTP)
        double doneAt = -1
        f.thenRun { doneAt = clock.seconds() }
        TransferResult r = settle(f)

        then:
        r.verified()
        channel.homeAsks == 1
        checkedByCrcAlone()
        MissionFtpFile.decode(server.files[MISSION]).items()[0].x() == 0
        doneAt < 0.5d
    }

    def "a vehicle whose home is set but never reported: after 1 s more the file is read back and found equal"() {
        given: 'the vehicle keeps its home as item 0, but its HOME_POSITION never reaches us'
        vehicleStoresAsArduPilot()
        channel.home = null

        when:
        TransferResult r = settle(upload(TransferPath.FTP))

        then:
        r.verified()
        server.requests['CalcFileCRC32'] == 1
        server.requests['OpenFileRO'] == 1
    }

    @Unroll
    def "#when: the file is read back and compared item by item"() {
        given:
        vehicleStoresAsArduPilot()
        setUp(this)

        when:
        TransferResult r = settle(upload(TransferPath.FTP))

        then:
        r.verified()
        server.requests['CalcFileCRC32'] == (crcAsked ? 1 : 0)
        server.requests['OpenFileRO'] == 1

        where:
        when                                                     | crcAsked | setUp
        'no home reported in 1 s, and the vehicle has one'       | true     | { it.channel.home = null }
        'the vehicle keeps a param2 not foreseen (CRC differs)'  | true     | { spec ->
            Closure stored = spec.server.keep
            spec.server.keep = { String path, byte[] b ->
                byte[] f = stored(path, b)
                MissionFtpFile.Contents c = MissionFtpFile.decode(f)
                List<MissionItem> items = new ArrayList<>(c.items())
                MissionItem last = items.last()
                items[-1] = new MissionItem(last.seq(), last.command(), last.frame(), last.param1(), 7f, last.param3(),
                        last.param4(), last.x(), last.y(), last.z(), last.autocontinue())
                MissionFtpFile.encode(c.type(), items)
            }
        }
        'the vehicle refuses CalcFileCRC32'                      | true     | { it.server.refuseCrc = true }
    }

    @Unroll
    def "#link: file bytes per FTP request and reply at most #most"() {
        given: 'no home reported, so the file is read back over the link too'
        channel.throughRadio = radio
        List<Integer> written = []
        List<Integer> read = []
        Closure toVehicle = channel.receiver
        channel.receiver = { MAVLinkMessage m ->
            if (m instanceof msg_file_transfer_protocol) {
                def p = dolphin.mavlink.ftp.FtpPayload.decode(m)
                if (p.opcode() == 7) { written << p.size() }
                if (p.opcode() == 5 || p.opcode() == 15) { read << p.size() }
            }
            toVehicle(m)
        }

        when:
        TransferResult r = settle(upload(TransferPath.FTP, MissionType.MISSION, intended()))

        then:
        r.verified()
        written.max() == Math.min(most, 10 + 5 * 38)
        written.sum() == 10 + 5 * 38
        read.every { it == most }

        where:
        link                 | radio | most
        'a radio'            | true  | 96
        'a link without one' | false | 239
    }

    def "ITEMS never uses FTP"() {
        when:
        TransferResult r = settle(upload(TransferPath.ITEMS))

        then:
        r.success()
        ftpMessages() == 0
        vehicle.stored == intended()
    }

    @Unroll
    def "a lossy, duplicating, reordering link (seed #seed): the FTP upload is verified"() {
        given:
        server.random = new Random(seed)
        server.lossUp = 0.15
        server.lossDown = 0.15
        server.duplicate = 0.1
        server.jitter = Duration.ofMillis(30)
        List<MissionItem> items = intended()

        when:
        TransferResult r = settle(upload(TransferPath.FTP))

        then:
        r.verified()
        MissionFtpFile.decode(server.files[MISSION]).items() == items

        where:
        seed << [11, 12, 13]
    }
}
