package app.migrate;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;

/**
 * What was read of the project before the plan: its layout, encoding and libraries.
 *
 * @param layout    its folders, read once (the test folders found outside them added)
 * @param encoding  its sources' encoding
 * @param strays    the test folders found outside those its build names
 * @param libraries the libraries its code uses
 * @param resolved  of those, the ones with a jar on this machine
 * @param relocated course classes kept in another course package, by the library's name for them
 */
record Project(Layout layout, SourceEncoding encoding, List<Path> strays, List<Libraries.Library> libraries,
        Map<Libraries.Library, Path> resolved, Map<String, String> relocated) {
}
