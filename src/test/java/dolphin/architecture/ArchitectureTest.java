package dolphin.architecture;

import static com.tngtech.archunit.library.Architectures.layeredArchitecture;
import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;

import com.tngtech.archunit.core.domain.JavaClass;
import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ImportOption;
import com.tngtech.archunit.junit.AnalyzeClasses;
import com.tngtech.archunit.junit.ArchTest;
import com.tngtech.archunit.lang.ArchRule;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Collectors;

/**
 * The layers of docs/architecture.md, lowest first: each may use only those below it, never one
 * above or beside it, and no two packages use each other, even through a third. One name, one
 * class: no two classes, nested ones included, share a simple name.
 */
@AnalyzeClasses(packages = "dolphin", importOptions = ImportOption.DoNotIncludeTests.class)
class ArchitectureTest {

    private static final String CORE = "core runtime";
    private static final String DSL = "script engine";
    private static final String LINK = "MAVLink link layer";
    private static final String MODEL = "mission model";
    private static final String SURVEYS = "mission surveys";
    private static final String FILES = "mission files";
    private static final String TRANSFER = "mission transfer";
    private static final String FLIGHT = "mission flight";
    private static final String LANGUAGE = "mission language";
    private static final String SENSORS = "sensors and payloads";
    private static final String PLATFORM = "MAVLink platform";
    private static final String SIMULATOR = "simulator";
    private static final String WEB = "web view";
    private static final String EDITOR = "editor support";
    private static final String CLI = "command line";

    @ArchTest
    static final ArchRule layersPointDownwards = layeredArchitecture().consideringOnlyDependenciesInLayers()
            .layer(CORE).definedBy("dolphin.core..")
            .layer(DSL).definedBy("dolphin.dsl..")
            .layer(LINK).definedBy("dolphin.mavlink..")
            .layer(MODEL).definedBy("dolphin.mission.model..")
            .layer(SURVEYS).definedBy("dolphin.mission.survey..")
            .layer(FILES).definedBy("dolphin.mission.file..")
            .layer(TRANSFER).definedBy("dolphin.mission.transfer..")
            .layer(FLIGHT).definedBy("dolphin.mission.flight..")
            .layer(LANGUAGE).definedBy("dolphin.mission.dsl..")
            .layer(SENSORS).definedBy("dolphin.sensor..")
            .layer(PLATFORM).definedBy("dolphin.platform..")
            .layer(SIMULATOR).definedBy("dolphin.sim..")
            .layer(WEB).definedBy("dolphin.web..")
            .layer(EDITOR).definedBy("dolphin.editor..")
            .layer(CLI).definedBy("dolphin.cli..")
            .whereLayer(CORE).mayNotAccessAnyLayer()
            .whereLayer(DSL).mayOnlyAccessLayers(CORE)
            .whereLayer(LINK).mayOnlyAccessLayers(CORE, DSL)
            .whereLayer(MODEL).mayOnlyAccessLayers(CORE, DSL, LINK)
            .whereLayer(SURVEYS).mayOnlyAccessLayers(CORE, DSL, LINK, MODEL)
            .whereLayer(FILES).mayOnlyAccessLayers(CORE, DSL, LINK, MODEL, SURVEYS)
            .whereLayer(TRANSFER).mayOnlyAccessLayers(CORE, DSL, LINK, MODEL, SURVEYS)
            .whereLayer(FLIGHT).mayOnlyAccessLayers(CORE, DSL, LINK, MODEL, SURVEYS, TRANSFER)
            .whereLayer(LANGUAGE).mayOnlyAccessLayers(CORE, DSL, LINK, MODEL, SURVEYS, FILES, TRANSFER, FLIGHT)
            .whereLayer(SENSORS).mayOnlyAccessLayers(CORE, DSL, LINK)
            .whereLayer(PLATFORM).mayOnlyAccessLayers(CORE, DSL, LINK, MODEL, SURVEYS, FILES, TRANSFER, FLIGHT, LANGUAGE, SENSORS)
            .whereLayer(SIMULATOR).mayOnlyAccessLayers(CORE, DSL, LINK, MODEL, SURVEYS, FILES, TRANSFER, FLIGHT, LANGUAGE, SENSORS, PLATFORM)
            .whereLayer(WEB).mayOnlyAccessLayers(CORE, DSL, LINK, MODEL, SURVEYS, FILES, TRANSFER, FLIGHT, LANGUAGE, SENSORS, PLATFORM)
            .whereLayer(EDITOR).mayOnlyAccessLayers(CORE, DSL, LINK, MODEL, SURVEYS, FILES, TRANSFER, FLIGHT, LANGUAGE, SENSORS, PLATFORM)
            .whereLayer(CLI).mayOnlyAccessLayers(CORE, DSL, LINK, MODEL, SURVEYS, FILES, TRANSFER, FLIGHT, LANGUAGE, SENSORS, PLATFORM,
                    SIMULATOR, WEB, EDITOR);

    @ArchTest
    static final ArchRule noPackageCycles = slices().matching("dolphin.(**)").should().beFreeOfCycles();

    @ArchTest
    static void oneNameOneClass(JavaClasses classes) {
        Map<String, List<String>> byName = classes.stream()
                // Groovy's generated closure classes ($_closure1) and anonymous classes have no name of ours
                .filter(c -> !c.isAnonymousClass() && !c.getName().contains("$_") && !c.getSimpleName().isEmpty())
                .collect(Collectors.groupingBy(JavaClass::getSimpleName, TreeMap::new,
                        Collectors.mapping(JavaClass::getName, Collectors.toList())));
        Map<String, List<String>> shared = new TreeMap<>(byName);
        shared.values().removeIf(names -> names.size() < 2);
        if (!shared.isEmpty()) {
            throw new AssertionError("classes that share a simple name: " + shared);
        }
    }
}
