package dolphin.cli;

import dolphin.core.Position;
import dolphin.mavlink.Autopilot;
import dolphin.mavlink.codec.SigningKey;
import dolphin.mavlink.link.LinkUrl;
import dolphin.mission.file.MissionFormat;
import dolphin.mission.transfer.TransferPath;
import dolphin.sensor.FleetFile;
import dolphin.sim.VehicleKind;
import dolphin.web.WebAddress;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/** picocli converters: a bad value is a usage error (exit 2) with the reason. */
final class Converters {

    private Converters() {
    }

    static final class LinkUrlConverter implements ITypeConverter<LinkUrl> {
        @Override
        public LinkUrl convert(String value) {
            try {
                return LinkUrl.parse(value);
            } catch (IllegalArgumentException e) {
                throw new TypeConversionException(e.getMessage());
            }
        }
    }

    /** {@code [HOST:]PORT} of the web view. */
    /** A fleet file (docs/sensors.md, "Fleet files"), read when the option is parsed so its mistakes stop the command at once. */
    static final class FleetFileConverter implements ITypeConverter<FleetFile> {
        @Override
        public FleetFile convert(String value) {
            try {
                return FleetFile.read(Path.of(value));
            } catch (IllegalArgumentException | IOException e) {
                throw new TypeConversionException(e.getMessage());
            }
        }
    }

    static final class Web implements ITypeConverter<WebAddress> {
        @Override
        public WebAddress convert(String value) {
            try {
                return WebAddress.parse(value);
            } catch (IllegalArgumentException e) {
                throw new TypeConversionException(e.getMessage());
            }
        }
    }

    /** The autopilot of simulated vehicles: "ardupilot" or "px4", whatever the case. */
    static final class AutopilotConverter implements ITypeConverter<Autopilot> {
        @Override
        public Autopilot convert(String value) {
            return switch (value.toLowerCase(Locale.ROOT)) {
                case "ardupilot" -> Autopilot.ARDUPILOT;
                case "px4" -> Autopilot.PX4;
                default -> throw new TypeConversionException("unknown autopilot '" + value
                        + "': expected ardupilot or px4");
            };
        }
    }

    static final class VehicleKindConverter implements ITypeConverter<VehicleKind> {
        @Override
        public VehicleKind convert(String value) {
            try {
                return VehicleKind.parse(value);
            } catch (IllegalArgumentException e) {
                throw new TypeConversionException(e.getMessage());
            }
        }
    }

    /** How mission transfers travel: auto, ftp or items. */
    static final class TransferPathConverter implements ITypeConverter<TransferPath> {
        @Override
        public TransferPath convert(String value) {
            for (TransferPath p : TransferPath.values()) {
                if (p.label().equals(value)) {
                    return p;
                }
            }
            throw new TypeConversionException("'" + value + "' is not auto, ftp or items");
        }
    }

    /** A mission file format: plan, waypoints or geojson. */
    static final class Format implements ITypeConverter<MissionFormat> {
        @Override
        public MissionFormat convert(String value) {
            try {
                return MissionFormat.parse(value);
            } catch (IllegalArgumentException e) {
                throw new TypeConversionException(e.getMessage());
            }
        }
    }

    /** {@code lat,lon[,alt]} in degrees and metres above mean sea level, the altitude 0 (sea level) when left out. */
    static final class Home implements ITypeConverter<Position> {
        @Override
        public Position convert(String value) {
            String[] p = value.split(",", -1);
            try {
                if (p.length != 2 && p.length != 3) {
                    throw new NumberFormatException();
                }
                double lat = Double.parseDouble(p[0].strip());
                double lon = Double.parseDouble(p[1].strip());
                double alt = p.length == 3 ? Double.parseDouble(p[2].strip()) : 0;
                if (!Double.isFinite(alt)) {
                    throw new NumberFormatException();
                }
                if (!(Math.abs(lat) <= 90 && Math.abs(lon) <= 180)) {
                    throw new TypeConversionException("home '" + value + "': latitude must be in [-90, 90], longitude in [-180, 180]");
                }
                return Position.fromDegrees(lat, lon, alt);
            } catch (NumberFormatException e) {
                throw new TypeConversionException("home '" + value
                        + "': expected LAT,LON[,ALT], e.g. 38.43462,-8.86118 or 40.444233,-7.375234,820");
            }
        }
    }

    /** A file with 64 hex digits or a passphrase. */
    static final class SigningKeyConverter implements ITypeConverter<SigningKey> {
        @Override
        public SigningKey convert(String value) {
            try {
                return SigningKey.fromFile(Path.of(value));
            } catch (IOException e) {
                throw new TypeConversionException("cannot read the signing key file " + value + ": " + e.getMessage());
            }
        }
    }
}
