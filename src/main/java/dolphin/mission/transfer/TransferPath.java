package dolphin.mission.transfer;

/**
 * How a mission, fence or rally list travels (docs/decisions.md, "Transfers on lossy links"): the
 * MAVLink mission protocol, item by item, or the whole list as one file over MAVLink FTP
 * (ArduPilot's {@code @MISSION/mission.dat}, {@code fence.dat}, {@code rally.dat}).
 */
public enum TransferPath {
    /** FTP where the vehicle offers it (AUTOPILOT_VERSION's MAV_PROTOCOL_CAPABILITY_FTP), else items; items again if FTP fails. */
    AUTO,
    /** Always FTP; a vehicle without it fails the transfer. */
    FTP,
    /** Always the mission protocol. */
    ITEMS;

    /** "auto", "ftp", "items", as options spell them. */
    public String label() {
        return name().toLowerCase(java.util.Locale.ROOT);
    }
}
