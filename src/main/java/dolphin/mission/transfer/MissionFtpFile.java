package dolphin.mission.transfer;

import com.MAVLink.MAVLinkPacket;
import com.MAVLink.Messages.MAVLinkPayload;
import com.MAVLink.common.msg_mission_item_int;
import dolphin.mission.model.MissionItem;
import dolphin.mission.model.MissionType;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.ArrayList;
import java.util.List;

/**
 * A whole mission, fence or rally list as the one file ArduPilot reads and writes over MAVLink FTP
 * ({@code @MISSION/mission.dat}, {@code fence.dat}, {@code rally.dat}; docs/mavlink.md, "Mission
 * transfers over FTP"): a header of five little-endian uint16 (magic 0x763d, the MAV_MISSION_TYPE,
 * options, the first seq, the item count), then each item as a MISSION_ITEM_INT payload of
 * {@value #ITEM_BYTES} bytes in wire order.
 */
public final class MissionFtpFile {

    public static final int MAGIC = 0x763d;
    public static final int HEADER_BYTES = 10;
    public static final int ITEM_BYTES = msg_mission_item_int.MAVLINK_MSG_LENGTH;

    /** The header and items of a file read back. */
    public record Contents(MissionType type, int options, int start, List<MissionItem> items) {
    }

    private MissionFtpFile() {
    }

    /** The file's path on the vehicle: "@MISSION/mission.dat", "@MISSION/fence.dat", "@MISSION/rally.dat". */
    public static String path(MissionType type) {
        return switch (type) {
            case MISSION -> "@MISSION/mission.dat";
            case FENCE -> "@MISSION/fence.dat";
            case RALLY -> "@MISSION/rally.dat";
        };
    }

    /** The whole list as one file: start 0, no options (the vehicle replaces what it held). */
    public static byte[] encode(MissionType type, List<MissionItem> items) {
        ByteBuffer b = ByteBuffer.allocate(HEADER_BYTES + items.size() * ITEM_BYTES).order(ByteOrder.LITTLE_ENDIAN);
        b.putShort((short) MAGIC).putShort((short) type.wire()).putShort((short) 0).putShort((short) 0)
                .putShort((short) items.size());
        for (MissionItem item : items) {
            msg_mission_item_int m = item.toMessage(0, 0, type);
            m.isMavlink2 = true;
            MAVLinkPayload p = m.pack().payload;
            b.put(p.getData().array(), 0, ITEM_BYTES);
        }
        return b.array();
    }

    /**
     * The file's length once its header is known: the header and its items; -1 when {@code head}
     * is shorter than a header or is not one.
     */
    public static int length(byte[] head) {
        if (head.length < HEADER_BYTES) {
            return -1;
        }
        ByteBuffer b = ByteBuffer.wrap(head).order(ByteOrder.LITTLE_ENDIAN);
        if (Short.toUnsignedInt(b.getShort(0)) != MAGIC) {
            return -1;
        }
        return HEADER_BYTES + Short.toUnsignedInt(b.getShort(8)) * ITEM_BYTES;
    }

    /** The file read back; an IllegalArgumentException says what is wrong with it. */
    public static Contents decode(byte[] file) {
        if (file.length < HEADER_BYTES) {
            throw new IllegalArgumentException("a mission file needs a " + HEADER_BYTES + "-byte header, got " + file.length
                    + " bytes");
        }
        ByteBuffer b = ByteBuffer.wrap(file).order(ByteOrder.LITTLE_ENDIAN);
        int magic = Short.toUnsignedInt(b.getShort());
        if (magic != MAGIC) {
            throw new IllegalArgumentException(String.format("not a mission file: magic 0x%04x, expected 0x%04x", magic, MAGIC));
        }
        int wire = Short.toUnsignedInt(b.getShort());
        MissionType type = MissionType.of(wire);
        if (type == null) {
            throw new IllegalArgumentException("a mission file of unknown MAV_MISSION_TYPE " + wire);
        }
        int options = Short.toUnsignedInt(b.getShort());
        int start = Short.toUnsignedInt(b.getShort());
        int count = Short.toUnsignedInt(b.getShort());
        int expected = HEADER_BYTES + count * ITEM_BYTES;
        if (file.length < expected) {
            throw new IllegalArgumentException("the mission file says " + count + " items (" + expected + " bytes) but has "
                    + file.length + " bytes");
        }
        List<MissionItem> items = new ArrayList<>(count);
        for (int i = 0; i < count; i++) {
            MAVLinkPacket packet = new MAVLinkPacket(ITEM_BYTES, true);
            for (int k = 0; k < ITEM_BYTES; k++) {
                packet.payload.add(b.get());
            }
            MissionItem item = MissionItem.fromMessage(new msg_mission_item_int(packet));
            items.add(item.seq() == start + i ? item : item.withSeq(start + i));
        }
        return new Contents(type, options, start, items);
    }
}
