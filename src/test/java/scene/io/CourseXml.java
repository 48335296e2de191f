package scene.io;

/** The course's own scene file (its XML bonus), as the course wrote it: shared by the reader's tests. */
final class CourseXml {
    /** basicRenderTestTwoColors.xml: ambient light, a sphere and four triangles, no camera. */
    static final String TWO_COLORS = """
            <scene background-color="75 127 90">
            <ambient-light color="255 191 191"/>
            <geometries>
            <sphere center="0 0 -100" radius="50"/>
            <triangle p0="-100 0 -100" p1="0 100 -100" p2="-100 100 -100"/>
            <triangle p0="100 0 -100" p1="0 100 -100" p2="100 100 -100"/>
            <triangle p0="-100 0 -100" p1="0 -100 -100" p2="-100 -100 -100"/>
            <triangle p0="100 0 -100" p1="0 -100 -100" p2="100 -100 -100"/>
            </geometries>
            </scene>
            """;

    private CourseXml() {
    }
}
