package dolphin.dsl.check;

import dolphin.dsl.vocabulary.Word;
import groovy.lang.MetaMethod;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.codehaus.groovy.reflection.CachedClass;
import org.codehaus.groovy.reflection.CachedMethod;
import org.codehaus.groovy.reflection.ReflectionCache;
import org.codehaus.groovy.runtime.InvokerHelper;

/**
 * The methods a call of a name may reach on a class, and whether given argument types fit one, by
 * Groovy's own rules (its MetaClass and parameter conversions), so the checker agrees with the
 * runtime: an Integer fits a Number, a GString a String, a BigDecimal no int.
 */
final class Candidates {

    private Candidates() {
    }

    /** Looked up once per class and name: a MetaClass lists all its methods, Groovy's added ones, for each lookup. */
    private static final Map<Class<?>, Map<String, List<MetaMethod>>> ALL = new ConcurrentHashMap<>();
    private static final Map<Class<?>, Map<String, List<MetaMethod>>> WORDS = new ConcurrentHashMap<>();

    /** Every method of that name a Groovy call on an instance of the class reaches, Groovy's added ones included. */
    static List<MetaMethod> all(Class<?> type, String name) {
        return ALL.computeIfAbsent(type, t -> new ConcurrentHashMap<>()).computeIfAbsent(name,
                n -> List.copyOf(InvokerHelper.getMetaClass(type).respondsTo(null, n)));
    }

    /** The class's {@code @Word} methods of that name: a platform word class's other methods are not words. */
    static List<MetaMethod> words(Class<?> type, String name) {
        return WORDS.computeIfAbsent(type, t -> new ConcurrentHashMap<>()).computeIfAbsent(name, n -> Arrays.stream(type.getMethods())
                .filter(m -> m.getName().equals(n) && m.isAnnotationPresent(Word.class) && !m.isBridge())
                .map(m -> (MetaMethod) CachedMethod.find(m))
                .toList());
    }

    /** The public static methods of that name: a statically imported word. */
    static List<MetaMethod> statics(Class<?> type, String name) {
        return Arrays.stream(type.getMethods())
                .filter(m -> m.getName().equals(name) && Modifier.isStatic(m.getModifiers()))
                .map(m -> (MetaMethod) CachedMethod.find(m))
                .toList();
    }

    /** The first method that takes arguments of these types (null: a type the checker cannot know), or null. */
    static MetaMethod accepting(List<MetaMethod> methods, Class<?>[] arguments) {
        return methods.stream().filter(m -> accepts(m, arguments)).findFirst().orElse(null);
    }

    static boolean accepts(MetaMethod m, Class<?>[] args) {
        CachedClass[] params = m.getParameterTypes();
        int n = args.length;
        if (m.isVargsMethod() && n >= params.length - 1) {
            int last = params.length - 1;
            for (int i = 0; i < last; i++) {
                if (!fits(params[i], args[i])) {
                    return false;
                }
            }
            if (n == params.length && fits(params[last], args[last])) {
                return true;
            }
            CachedClass element = ReflectionCache.getCachedClass(params[last].getTheClass().getComponentType());
            for (int i = last; i < n; i++) {
                if (!fits(element, args[i])) {
                    return false;
                }
            }
            return true;
        }
        if (params.length == n) {
            for (int i = 0; i < n; i++) {
                if (!fits(params[i], args[i])) {
                    return false;
                }
            }
            return true;
        }
        // Groovy passes null to a single object parameter when the call has no argument
        return params.length == 1 && n == 0 && !params[0].isPrimitive;
    }

    private static boolean fits(CachedClass param, Class<?> arg) {
        return arg == null || param.isAssignableFrom(arg);
    }

    /** The declared method behind a MetaMethod, when it is one (not one of Groovy's additions). */
    static Method method(MetaMethod m) {
        return m instanceof CachedMethod c ? c.getCachedMethod() : null;
    }
}
