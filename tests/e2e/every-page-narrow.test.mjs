/** Every page of the book on a narrow phone, 360 px wide, each loaded once for all the checks of every-page.mjs. */
import { sweepEveryPage } from './every-page.mjs';

sweepEveryPage(360);
