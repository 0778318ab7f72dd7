package dolphin.mavlink;

import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/** Names of the values of a generated MAVLink enum class (e.g. COPTER_MODE), with its prefix removed. */
public final class EnumNames {

    private record Key(Class<?> type, String prefix) {
    }

    private static final Map<Key, Map<Long, String>> CACHE = new ConcurrentHashMap<>();

    private EnumNames() {
    }

    /** value -> name without {@code prefix}, e.g. 3 -> "AUTO" for COPTER_MODE with prefix "COPTER_MODE_". */
    public static Map<Long, String> of(Class<?> enumClass, String prefix) {
        return CACHE.computeIfAbsent(new Key(enumClass, prefix), key -> {
            Class<?> c = key.type();
            Map<Long, String> names = new LinkedHashMap<>();
            for (Field f : c.getFields()) {
                if (Modifier.isStatic(f.getModifiers()) && (f.getType() == int.class || f.getType() == long.class)
                        && f.getName().startsWith(prefix) && !f.getName().endsWith("_ENUM_END")) {
                    try {
                        names.putIfAbsent(((Number) f.get(null)).longValue(), f.getName().substring(prefix.length()));
                    } catch (IllegalAccessException e) {
                        throw new IllegalStateException(e);
                    }
                }
            }
            return Collections.unmodifiableMap(names);
        });
    }

    /** The name of a value, or the number itself when the enum has no such value. */
    public static String name(Class<?> enumClass, String prefix, long value) {
        String n = of(enumClass, prefix).get(value);
        return n != null ? n : String.valueOf(value);
    }
}
