package raytracer.samplers;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** The grid side is the smallest k &gt;= 1 with k * k &gt;= n, at perfect squares, just past them and at the int range's end. */
class SquareCountTest {

    @Test
    void sideIsTheSmallestSquareNotBelowTheRequest() {
        assertEquals(1, SquareCount.side(0), "no request still takes one sample");
        assertEquals(1, SquareCount.side(1));
        for (int k = 1; k <= 2000; k++) {
            assertEquals(k, SquareCount.side(k * k), "a perfect square is its own grid: " + k * k);
            assertEquals(k + 1, SquareCount.side(k * k + 1), "one past a square needs the next side: " + (k * k + 1));
            assertEquals(k * k, SquareCount.roundUp((k - 1) * (k - 1) + 1));
        }
        // 46340^2 = 2,147,395,600 <= 2^31 - 1 < 46341^2
        assertEquals(46340, SquareCount.side(46340 * 46340));
        assertEquals(46341, SquareCount.side(Integer.MAX_VALUE));
    }
}
