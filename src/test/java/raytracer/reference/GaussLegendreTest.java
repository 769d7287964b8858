package raytracer.reference;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The rule integrates x^k over [0, 1] exactly up to k = 2n - 1, and not beyond. */
class GaussLegendreTest {

    private static double integrate(GaussLegendre rule, int k) {
        double sum = 0;
        for (int i = 0; i < rule.order(); i++) {
            sum += rule.weight(i) * Math.pow(rule.node(i), k);
        }
        return sum;
    }

    @ParameterizedTest
    @ValueSource(ints = {1, 2, 3, 4, 7, 8, 16})
    void exactForPolynomialsUpToDegreeTwoNMinusOne(int n) {
        GaussLegendre rule = new GaussLegendre(n);
        for (int k = 0; k <= 2 * n - 1; k++) {
            assertEquals(1.0 / (k + 1), integrate(rule, k), 1e-14, "x^" + k + " with " + n + " points");
        }
        // degree 2n is the first it misses
        assertTrue(Math.abs(integrate(rule, 2 * n) - 1.0 / (2 * n + 1)) > 1e-14 * Math.pow(4, -n),
                   "x^" + 2 * n + " should not be exact with " + n + " points");
        for (int i = 0; i < n; i++) {
            assertTrue(rule.node(i) > 0 && rule.node(i) < 1 && rule.weight(i) > 0);
            assertEquals(rule.node(i), 1 - rule.node(n - 1 - i), 1e-15, "nodes are symmetric");
        }
    }
}
