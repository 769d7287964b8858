package raytracer.io.scene;

import java.util.AbstractSet;
import java.util.Collections;
import java.util.Iterator;

/** The key set of a mapping whose keys are names chosen by the user (materials), or not checked yet. */
final class AnyName extends AbstractSet<String> {
    static final AnyName INSTANCE = new AnyName();

    private AnyName() {
    }

    @Override
    public boolean contains(Object o) {
        return true;
    }

    @Override
    public Iterator<String> iterator() {
        return Collections.emptyIterator();
    }

    @Override
    public int size() {
        return 0;
    }
}
