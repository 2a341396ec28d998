/** Every page of the book on a phone, 390 px wide and then narrowed to 360 px, each loaded once for all the checks of every-page.mjs. */
import { sweepEveryPage } from './every-page.mjs';

sweepEveryPage(390);
