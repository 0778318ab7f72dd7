package dolphin.mavlink.ftp;

import com.MAVLink.common.msg_file_transfer_protocol;
import java.util.Arrays;

/**
 * The 251-byte payload of FILE_TRANSFER_PROTOCOL (docs/mavlink.md, "Mission transfers over FTP"):
 * seq (uint16 LE), session, opcode, size, req_opcode, burst_complete, a padding byte, offset
 * (uint32 LE) and up to {@value #DATA_BYTES} bytes of data.
 */
record FtpPayload(int seq, int session, int opcode, int size, int reqOpcode, boolean burstComplete, long offset,
                  byte[] data) {

    static final int PAYLOAD_BYTES = 251;
    static final int DATA_BYTES = 239;

    static final int TERMINATE_SESSION = 1;
    static final int RESET_SESSIONS = 2;
    static final int OPEN_FILE_RO = 4;
    static final int READ_FILE = 5;
    static final int CREATE_FILE = 6;
    static final int WRITE_FILE = 7;
    static final int CALC_FILE_CRC32 = 14;
    static final int BURST_READ_FILE = 15;
    static final int ACK = 128;
    static final int NAK = 129;

    FtpPayload {
        data = data == null ? new byte[0] : data;
        if (data.length > DATA_BYTES) {
            throw new IllegalArgumentException("an FTP payload carries at most " + DATA_BYTES + " bytes, got " + data.length);
        }
    }

    /** A request: its data (a path, or bytes to write) sized by {@code size}. */
    static FtpPayload request(int seq, int session, int opcode, int size, long offset, byte[] data) {
        return new FtpPayload(seq, session, opcode, size, 0, false, offset, data);
    }

    /** The same payload with another seq. */
    FtpPayload withSeq(int newSeq) {
        return new FtpPayload(newSeq & 0xffff, session, opcode, size, reqOpcode, burstComplete, offset, data);
    }

    static FtpPayload decode(msg_file_transfer_protocol m) {
        short[] p = m.payload;
        int size = p[4] & 0xff;
        byte[] data = new byte[Math.min(size, DATA_BYTES)];
        for (int i = 0; i < data.length; i++) {
            data[i] = (byte) p[12 + i];
        }
        long offset = (p[8] & 0xff) | (p[9] & 0xff) << 8 | (p[10] & 0xff) << 16 | (long) (p[11] & 0xff) << 24;
        return new FtpPayload((p[0] & 0xff) | (p[1] & 0xff) << 8, p[2] & 0xff, p[3] & 0xff, size, p[5] & 0xff,
                p[6] != 0, offset, data);
    }

    msg_file_transfer_protocol toMessage(int targetSystem, int targetComponent) {
        msg_file_transfer_protocol m = new msg_file_transfer_protocol();
        m.target_system = (short) targetSystem;
        m.target_component = (short) targetComponent;
        short[] p = m.payload;
        p[0] = (short) (seq & 0xff);
        p[1] = (short) (seq >> 8 & 0xff);
        p[2] = (short) session;
        p[3] = (short) opcode;
        p[4] = (short) size;
        p[5] = (short) reqOpcode;
        p[6] = (short) (burstComplete ? 1 : 0);
        for (int i = 0; i < 4; i++) {
            p[8 + i] = (short) (offset >> 8 * i & 0xff);
        }
        for (int i = 0; i < data.length; i++) {
            p[12 + i] = (short) (data[i] & 0xff);
        }
        return m;
    }

    /** A NAK's MAV_FTP_ERR (data[0]), or -1. */
    int error() {
        return opcode == NAK && data.length > 0 ? data[0] & 0xff : -1;
    }

    /** A FailErrno NAK's errno (data[1]), or -1. */
    int errno() {
        return opcode == NAK && data.length > 1 ? data[1] & 0xff : -1;
    }

    /** "OpenFileRO", "BurstReadFile", "ACK": MAV_FTP_OPCODE as ArduPilot names it. */
    static String opcodeName(int opcode) {
        return switch (opcode) {
            case 0 -> "None";
            case TERMINATE_SESSION -> "TerminateSession";
            case RESET_SESSIONS -> "ResetSessions";
            case 3 -> "ListDirectory";
            case OPEN_FILE_RO -> "OpenFileRO";
            case READ_FILE -> "ReadFile";
            case CREATE_FILE -> "CreateFile";
            case WRITE_FILE -> "WriteFile";
            case 8 -> "RemoveFile";
            case 9 -> "CreateDirectory";
            case 10 -> "RemoveDirectory";
            case 11 -> "OpenFileWO";
            case 12 -> "TruncateFile";
            case 13 -> "Rename";
            case 14 -> "CalcFileCRC32";
            case BURST_READ_FILE -> "BurstReadFile";
            case ACK -> "ACK";
            case NAK -> "NAK";
            default -> "opcode " + opcode;
        };
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof FtpPayload p && seq == p.seq && session == p.session && opcode == p.opcode && size == p.size
                && reqOpcode == p.reqOpcode && burstComplete == p.burstComplete && offset == p.offset
                && Arrays.equals(data, p.data);
    }

    @Override
    public int hashCode() {
        return 31 * java.util.Objects.hash(seq, session, opcode, size, reqOpcode, burstComplete, offset) + Arrays.hashCode(data);
    }

    @Override
    public String toString() {
        String req = opcode >= ACK ? " to " + opcodeName(reqOpcode) : "";
        String err = opcode == NAK ? " " + FtpException.errorName(error()) : "";
        return opcodeName(opcode) + req + err + " seq " + seq + " session " + session + " offset " + offset + " size " + size
                + (burstComplete ? " burst complete" : "");
    }
}
