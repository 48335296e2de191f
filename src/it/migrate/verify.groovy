// After `raytracer migrate course` and `mvn test` in course/: the course classes moved, the
// student's extras kept, the test that calls the student's own method left out, and every kept
// test class ran and passed, the one not named *Test included, and the JUnit 4 one (Vintage).
def course = new File(basedir, 'course')
assert new File(course, 'course-backup/src/primitives/Vector.java').isFile() : 'Vector.java not in course-backup/'
assert !new File(course, 'src/primitives/Vector.java').exists() : 'the course Vector still in src/'
assert new File(course, 'src/geometries/Cube.java').isFile() : 'the extra shape was not kept'
assert new File(course, 'unittests/primitives/RotateTest.java').isFile() : 'the left-out test was moved'
assert new File(course, 'pom.xml').text.contains('<testExclude>primitives/RotateTest.java</testExclude>')
def reports = new File(course, 'target/surefire-reports')
def ran = reports.listFiles().findAll { it.name.startsWith('TEST-') && it.name.endsWith('.xml') }.collect {
    def suite = new groovy.xml.XmlSlurper().parse(it)
    assert suite.@failures.toInteger() == 0 && suite.@errors.toInteger() == 0 : "${suite.@name} failed"
    suite.@name.toString()
}
assert ran.toSet() == ['primitives.VectorTests', 'renderer.CameraIntersectionIntegration', 'geometries.CubeTests',
        'primitives.PointJUnit4Test'].toSet() : "ran ${ran}"
def pom = new File(course, 'pom.xml').text
assert pom.contains('<artifactId>junit-vintage-engine</artifactId>') : 'no Vintage engine for the JUnit 4 test'
true
